#pragma once
// What clear water shows under its surface besides the floor and the rim's walls, which water.frag
// traces itself: the islands' walls and the bodies below y = 0, drawn from the camera (unrefracted)
// into a layer (render/layer_target.h) the frame's size, before the main pass, when there is any
// (view::FramePlan::submerged). Each texel holds the linear colour of what it shows (x: RGBA8,
// packUnorm4x8) and the view depths (clip w, y: packHalf2x16) where the eye's line through it enters
// (0: nothing) and leaves the body or wall. water.frag marches its refracted ray through the
// layer in clip space (submerged_seen), so the walls and the bodies bend with the waves as the
// floor does.
#include "gpu/context.h"
#include "render/layer_target.h"

namespace pond::render {

// A sampled colour attachment in this format is a feature every Vulkan device has; integer, so
// read texel by texel (nearest) and never blended.
inline constexpr vk::Format kSubmergedFormat = vk::Format::eR32G32Uint;

}  // namespace pond::render
