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

// The barriers before the pass: both images to attachment layouts (contents discarded).
std::array<vk::ImageMemoryBarrier2, 2> layer_pass_begin(const LayerTarget& t);
// Records the pass (between layer_pass_begin() and layer_pass_end(), which the caller records,
// batched with other passes' barriers: render/barrier_batch.h): cleared, viewport and scissor the
// target's, `draw()` inside.
void record_layer_pass(const vk::raii::CommandBuffer& cmd, const LayerTarget& t, const std::function<void()>& draw);
// The barrier after it: the colour image to shader-read for the water's fragment shader.
vk::ImageMemoryBarrier2 layer_pass_end(const LayerTarget& t);
// A frame that does not draw the layer still binds it (the descriptor set is whole): the barrier
// that puts its colour image in the shader-read layout.
vk::ImageMemoryBarrier2 layer_unused(const LayerTarget& t);

}  // namespace pond::render
