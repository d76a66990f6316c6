#pragma once
// The planar reflection of everything above the water (its pass in render/early_passes.cpp draws it
// when FrameView::effects.reflections is on): the land and the pass drawables (the tree) mirrored
// about the water's rest plane y = 0, only what lies above that plane (view::mirrored_walls), into a
// colour target at the frame's resolution, cleared to transparent. water_reflect.frag samples it at the
// pixel's screen position shifted by the surface normal and falls back to the sky where it is
// transparent (alpha 0: nothing above the water there), so nothing below the water and nothing
// in front of it is reflected.
//
// The target holds linear colour in R8G8B8A8_UNORM (its pipelines are GraphicsPipelineDesc::
// linear_output: no encoding), which the water mixes as it is: no sRGB encoding on store or
// decoding on sampling, which llvmpipe pays per pixel (docs/perf.md). A sampled colour attachment
// in that format is a feature every Vulkan device has.
#include "gpu/context.h"
#include "render/frame_constants.h"
#include "render/layer_target.h"

namespace pond::render {

inline constexpr vk::Format kReflectionFormat = vk::Format::eR8G8B8A8Unorm;
// Per axis. At 2, read nearest, thin casters (twigs, a trunk a few pixels wide) broke into blocks at
// grazing angles, and a bilinear read smoothed the blocks without joining them (docs/perf.md).
inline constexpr std::uint32_t kReflectionDivisor = 1;

// The reflection's size for a frame of `frame` pixels (at least 1 x 1); its target is a LayerTarget
// (render/layer_target.h) of that size in kReflectionFormat.
vk::Extent2D reflection_extent(vk::Extent2D frame);

// The sampler the water's layers and the caustics map are bound with: nearest, clamped to the edge
// (the water reads them with texelFetch, clamping the coordinates itself).
vk::raii::Sampler create_reflection_sampler(const gpu::Context& ctx);

}  // namespace pond::render
