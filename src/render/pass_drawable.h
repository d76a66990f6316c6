#pragma once
// What draws itself into a frame's passes besides the water and the land (the wind tree, the
// bodies, the demo's panel), and the per-frame values it is given.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "sim/session.h"
#include "view/sun_shadow.h"
#include "view/view_spec.h"

namespace pond::render {

struct FrameInfo {
  const vk::raii::CommandBuffer& cmd;
  std::uint32_t slot;           // frame slot in [0, kFramesInFlight): index per-slot resources
  const float* view_proj;       // column-major 4x4, Vulkan clip space (y down, depth 0..1)
  std::array<float, 3> eye;
  vk::Extent2D extent;
  const sim::Session& session;         // what is drawn, as it is now (const: nothing here waits)
  const view::LightingSpec& lighting;  // the scene's, with the session's sun
  // The bodies' states this frame draws, on the host (grid units): read in the frame's one wait.
  std::span<const sim::BodyState> body_states;
  // The bodies' states this frame draws (grid units, sim::BodyState): the GPU solver's own buffer,
  // or the CPU solver's copied into the slot's; null without bodies.
  const gpu::Buffer* bodies = nullptr;
  float pixel_scale = 1.0f;     // the target's pixels per frame pixel (the reflection's: 1/2)
};

// Its pipelines must be created for the frame's colour format (FrameLoop::color_format()) and
// kDepthFormat (render/frame_constants.h) with dynamic rendering.
class PassDrawable {
 public:
  virtual ~PassDrawable() = default;
  // Before the frame's passes, with the slot's previous use finished: write per-slot uniforms, etc.
  // What the front end may change between the frame's halves (the demo's panel) is read in the
  // draw calls instead.
  virtual void prepare(const FrameInfo& /*frame*/) {}
  // Inside the main pass (viewport, scissor set; depth test on): bind and draw.
  virtual void draw(const FrameInfo& frame) = 0;
  // Inside the planar reflection's pass (render/reflection_pass.h: kReflectionFormat, kDepthFormat;
  // frame.extent and frame.pixel_scale are the reflection's): draw mirrored about y = 0. Drawables
  // that are not above the water (the demo's panel) draw nothing.
  virtual void draw_reflected(const FrameInfo& /*frame*/) {}
  // Inside the submerged layer's pass (render/submerged_pass.h: kSubmergedFormat, kDepthFormat):
  // draw what lies below y = 0 (its colour and view depths: that header). Its shadow casters'
  // boxes below y = 0 say where (view::plan_frame).
  virtual void draw_submerged(const FrameInfo& /*frame*/) {}
  // Inside the main pass, before the scene: opaque screen-space overlays (the demo's panel) that
  // write the nearest depth, so the scene's fragments behind them fail the depth test before they
  // are shaded (on llvmpipe the water's shading is most of what a pixel under the panel costs).
  virtual void draw_occluding(const FrameInfo& /*frame*/) {}
  // After prepare(): the boxes (world) of what this drawable casts into the sun's shadow map,
  // which is fitted to them (view/frame_plan.h). None: it casts nothing.
  virtual void add_shadow_casters(std::vector<view::ShadowCaster>& /*casters*/) const {}
  // Inside the shadow map's pass (depth only, kShadowFormat; frame.view_proj is the sun's
  // orthographic projection, frame.extent the map's size): draw the casters, depth only.
  virtual void draw_shadow(const FrameInfo& /*frame*/) {}
};

}  // namespace pond::render
