#pragma once
// The graphics pipelines of the water renderer, all for dynamic rendering into one color format
// plus a depth buffer, sharing one descriptor-set layout (shared/water_render.h bindings):
//  - land:  shore, islands, pool rim (LandVertex buffer);
//  - water: the surface pulled from the state and normal buffers by node index;
//  - wire:  the same triangles as lines over the water (the LOD overlay); null when the device
//           lacks fillModeNonSolid;
//  - waters: the water for each set of effects (water_for): sampling the planar reflection
//    (render/reflection_pass.h), lighting the floor with the caustics map (render/caustics_pass.h;
//    POND_SPEC_CAUSTICS), sampling the sun's shadow map (render/shadow_pass.h; POND_SPEC_SHADOWS),
//    showing what lies under the surface (render/submerged_pass.h; POND_SPEC_SUBMERGED), so an
//    effect that is off costs nothing;
//  - land_mirror: the land above the water mirrored about y = 0, for the reflection's target;
//  - land_submerged: the islands' walls under the water, for the submerged layer (its colour and,
//    in alpha, the view depth: render/submerged_pass.h);
//  - sky:   a box standing on the land's outer edge (view::sky_box), drawn last (depth test, no
//           write), so it shades only what nothing else covered;
//  - land_shadowed: the land sampling the sun's shadow map, used in frames that have one.
// The land and the waters test depth with "less" (render/frame_loop.cpp draws them twice where
// shadows fall); the rest with "less or equal".
// No culling: large splashes may fold the surface over.
#include <span>
#include <vector>

#include "gpu/context.h"

namespace pond::render {

struct WaterPipelines {
  // The set's bindings (shared/water_render.h's, then the passes'), and its layout.
  std::vector<vk::DescriptorSetLayoutBinding> set_bindings;
  vk::raii::DescriptorSetLayout set_layout = nullptr;
  vk::raii::PipelineLayout layout = nullptr;
  vk::raii::Pipeline land = nullptr;
  vk::raii::Pipeline land_shadowed = nullptr;
  std::vector<vk::raii::Pipeline> waters;  // by water_variant()
  vk::raii::Pipeline land_mirror = nullptr;
  vk::raii::Pipeline land_submerged = nullptr;
  vk::raii::Pipeline wire = nullptr;
  vk::raii::Pipeline sky = nullptr;

  // The index in `waters` of the water drawn with these effects.
  static constexpr std::size_t kWaterVariants = 16;
  static std::size_t water_variant(bool reflections, bool caustics, bool shadows, bool submerged) {
    return (reflections ? 1u : 0u) | (caustics ? 2u : 0u) | (shadows ? 4u : 0u) | (submerged ? 8u : 0u);
  }
  const vk::raii::Pipeline& water_for(bool reflections, bool caustics, bool shadows, bool submerged) const {
    return waters[water_variant(reflections, caustics, shadows, submerged)];
  }
};

// `pass_bindings`: those the passes add to the set (FramePass::water_bindings); InternalError for a
// number taken twice.
WaterPipelines create_water_pipelines(const gpu::Context& ctx, vk::Format color_format, vk::Format depth_format,
                                      std::span<const vk::DescriptorSetLayoutBinding> pass_bindings);

}  // namespace pond::render
