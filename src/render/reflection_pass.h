#pragma once
// The planar reflection of everything above the water (frame_loop.h draws it first each frame when
// FrameView::effects.reflections is on): the land and the pass drawables (the tree) mirrored about
// the water's rest plane y = 0, only what lies above that plane (view::mirrored_walls), into a colour target at
// the frame's resolution, cleared to transparent. water_reflect.frag samples it at the
// pixel's screen position shifted by the surface normal and falls back to the sky where it is
// transparent (alpha 0: nothing above the water there), so nothing below the water and nothing
// in front of it is reflected.
//
// The target holds linear colour in R8G8B8A8_UNORM (its pipelines are GraphicsPipelineDesc::
// linear_output: no encoding), which the water mixes as it is: no sRGB encoding on store or
// decoding on sampling, which llvmpipe pays per pixel (docs/perf.md). A sampled colour attachment
// in that format is a feature every Vulkan device has.
#include <array>
#include <functional>

#include "gpu/context.h"
#include "render/frame_constants.h"
#include "render/render_target.h"

namespace pond::render {

inline constexpr vk::Format kReflectionFormat = vk::Format::eR8G8B8A8Unorm;
inline constexpr vk::Format kReflectionDepthFormat = kDepthFormat;
// Per axis. At 2, read nearest, thin casters (twigs, a trunk a few pixels wide) broke into blocks at
// grazing angles, and a bilinear read smoothed the blocks without joining them (docs/perf.md).
inline constexpr std::uint32_t kReflectionDivisor = 1;

// The reflection's size for a frame of `frame` pixels (at least 1 x 1).
vk::Extent2D reflection_extent(vk::Extent2D frame);

// One frame slot's reflection: colour (sampled by the water) and depth.
struct ReflectionTarget {
  Image color, depth;
};

// (Re)creates `t` when its size is not reflection_extent(frame); returns whether it did (the
// descriptor pointing at the colour view must then be rewritten).
bool ensure_reflection_target(const gpu::Context& ctx, ReflectionTarget& t, vk::Extent2D frame);

// The barriers before the pass: both images to attachment layouts (contents discarded).
std::array<vk::ImageMemoryBarrier2, 2> reflection_pass_begin(const ReflectionTarget& t);
// Records the pass (between reflection_pass_begin() and reflection_pass_end(), which the caller
// records, batched with other passes' barriers: render/barrier_batch.h): cleared, viewport and
// scissor the target's, `draw()` inside.
void record_reflection_pass(const vk::raii::CommandBuffer& cmd, const ReflectionTarget& t,
                            const std::function<void()>& draw);
// The barrier after it: the colour image to shader-read for the water's fragment shader.
vk::ImageMemoryBarrier2 reflection_pass_end(const ReflectionTarget& t);

// The sampler the water reads the reflection with: bilinear, clamped to the edge (a ripple's shift
// past the border repeats the border's texel).
vk::raii::Sampler create_reflection_sampler(const gpu::Context& ctx);

}  // namespace pond::render
