#pragma once
// The graphics pipelines of the water renderer, all for dynamic rendering into one color format
// plus a depth buffer, sharing one descriptor-set layout (shared/water_render.h bindings):
//  - land:  shore, islands, pool rim (LandVertex buffer);
//  - water: the surface pulled from the state and normal buffers by node index;
//  - wire:  the same triangles as lines over the water (the LOD overlay); null when the device
//           lacks fillModeNonSolid;
//  - water_reflect: the water sampling the planar reflection (render/reflection_pass.h);
//  - water_caustics, water_reflect_caustics: the two above lighting the floor with the caustics
//    map (render/caustics_pass.h; POND_SPEC_CAUSTICS), so the effect costs nothing when off;
//  - land_mirror: the land above the water mirrored about y = 0, for the reflection's target;
//  - sky:   a box standing on the land's outer edge (view::sky_box), drawn last (depth test, no
//           write), so it shades only what nothing else covered.
// No culling: large splashes may fold the surface over.
#include "gpu/context.h"

namespace pond::render {

struct WaterPipelines {
  vk::raii::DescriptorSetLayout set_layout = nullptr;
  vk::raii::PipelineLayout layout = nullptr;
  vk::raii::Pipeline land = nullptr;
  vk::raii::Pipeline water = nullptr;
  vk::raii::Pipeline water_reflect = nullptr;
  vk::raii::Pipeline water_caustics = nullptr;
  vk::raii::Pipeline water_reflect_caustics = nullptr;
  vk::raii::Pipeline land_mirror = nullptr;
  vk::raii::Pipeline wire = nullptr;
  vk::raii::Pipeline sky = nullptr;

  // The water's pipeline for a frame's effects.
  const vk::raii::Pipeline& water_for(bool reflections, bool caustics) const {
    if (caustics) return reflections ? water_reflect_caustics : water_caustics;
    return reflections ? water_reflect : water;
  }
};

WaterPipelines create_water_pipelines(const gpu::Context& ctx, vk::Format color_format, vk::Format depth_format);

}  // namespace pond::render
