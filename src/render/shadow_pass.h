#pragma once
// The sun's shadow map (its pass in render/early_passes.cpp draws it when FrameView::effects.shadows
// is on and something casts): the pass drawables' casters (the trees, the bodies:
// PassDrawable::draw_shadow) drawn depth-only, orthographically along the sunlight, into a square
// depth image fitted to their bounding spheres (view/sun_shadow.h). The land and the water sample
// it with a depth-compare sampler (shared/shadow_sampling.h): the land's sunlit part, the water's
// glint and diffuse light, and the pool floor seen through the water where its sunlight entered.
//
// Only the trees and the bodies cast, and neither the land nor the water is drawn into the map,
// so the receivers cannot shade themselves: no acne, and no depth bias to detach a shadow from
// the trunk's foot (peter-panning). The casters' own light comes from their N.L.
//
// Filtering: the shaders compare the four texels around a point in one gather and blend them
// bilinearly (a 2x2 percentage-closer filter, a soft edge a texel wide), the same on every device:
// the hardware's linear compare filter needs SAMPLED_IMAGE_FILTER_LINEAR on the depth format, which
// the spec does not require (lavapipe lacks it for D16). The sampler's border is the far depth, so
// points beyond the casters' bounds compare as lit.
#include <functional>

#include "gpu/context.h"
#include "render/render_target.h"

namespace pond::render {

inline constexpr vk::Format kShadowFormat = vk::Format::eD16Unorm;  // sampled and attachment on every device

// (Re)creates `map` (one frame slot's, idle) when it is not `size` x `size` texels.
void ensure_shadow_map(const gpu::Context& ctx, Image& map, std::uint32_t size);

// Records the pass (the map in the depth-attachment layout: the barriers are the pass list's,
// render/frame_pass.h): the map cleared to the far depth, viewport and scissor the map's, `draw()`
// inside.
void record_shadow_pass(const vk::raii::CommandBuffer& cmd, const Image& map, const std::function<void()>& draw);

// The depth-compare sampler (less or equal: lit where no deeper than the stored caster), nearest,
// clamped to an opaque white (far) border.
vk::raii::Sampler create_shadow_sampler(const gpu::Context& ctx);

}  // namespace pond::render
