#pragma once
// An offscreen layer the main pass's water samples (render/reflection_pass.h, the mirror image;
// render/submerged_pass.h, what lies under the surface): a colour image and a depth image of one
// size, cleared to transparent black each frame, drawn in the early command buffer, then read by
// the water's fragment shader (one texel per pixel, texelFetch).
#include <array>
#include <functional>
#include <string>

#include "gpu/context.h"
#include "render/render_target.h"

namespace pond::render {

struct LayerTarget {
  Image color, depth;
};

// (Re)creates `t` when its size or colour format is not `extent` and `format`; returns whether it
// did (the descriptor pointing at the colour view must then be rewritten).
bool ensure_layer_target(const gpu::Context& ctx, LayerTarget& t, vk::Extent2D extent, vk::Format format,
                         const std::string& name);

// Records the pass that draws into `t` (its images in attachment layouts: the barriers are the
// pass list's, render/frame_pass.h): cleared, viewport and scissor the target's, `draw()` inside.
void record_layer_pass(const vk::raii::CommandBuffer& cmd, const LayerTarget& t, const std::function<void()>& draw);

}  // namespace pond::render
