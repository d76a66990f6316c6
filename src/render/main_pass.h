#pragma once
// The main pass: dynamic rendering into the frame's target and depth buffer of, in order, the
// occluding overlays (the demo's panel), the land and the water (first where a shadow can fall,
// with the shaders that sample the sun's map, then everywhere with those that do not), the LOD
// wireframe, the pass drawables (the trees, the bodies) and the sky's box last; with the barriers
// that put the target in and out of the attachment layout, and the one that keeps the next
// submissions' compute from overwriting the state this pass still reads.
#include <array>

#include "render/frame_context.h"
#include "render/frame_target.h"

namespace pond::render {

struct MainPassOptions {
  bool wireframe = false;  // the LOD triangles over the water
  bool reflections = false, caustics = false, submerged = false;  // which water pipeline (water_pipeline.h)
  std::array<double, 3> sky{};  // the zenith's colour (linear): the background is its horizon
};

void record_main_pass(const vk::raii::CommandBuffer& cmd, const FrameContext& frame, const FrameTarget& target,
                      const MainPassOptions& options);

}  // namespace pond::render
