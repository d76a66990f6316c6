#pragma once
// The one frame loop of pond, shared by `pond render` (offscreen image) and the windowed demo
// (swapchain image). It draws the simulation session it is given (sim/session.h) and owns no
// simulation state: the front end makes splashes, edits and solver switches on the session, and
// the loop advances it by the frame's steps. One frame is one pass down the pipeline of
// ARCHITECTURE.md:
//
//   substeps (the session's solver: GPU compute or CPU) -> normals -> the passes before the main
//     one, submitted (the caustics' compute pass when on, render/caustics_pass.h; the sun's shadow
//     map when on, render/shadow_pass.h; the planar reflection's pass when on,
//     render/reflection_pass.h) -> LOD (CPU, from the new positions, while the device draws those
//     passes) -> the main pass: dynamic rendering into the caller's image (land, water, LOD
//     wireframe, extra drawables, sky)
//
// Synchronization: the compute work (substeps + normals) is submitted and waited for, because the
// CPU LOD builder needs this frame's positions (read straight from the state memory when it is
// host-visible, as on lavapipe, else copied back). The early passes are recorded into the frame
// slot's first command buffer and the main pass into its second, submitted after them on the same
// queue: the early one starts with a compute -> vertex-shader barrier (both read the state and
// normals buffers as storage buffers; a barrier covers what is submitted after it), and the main
// one ends with a vertex-shader -> compute barrier so the next frame's substeps cannot overwrite a
// buffer the draw still reads. Index buffers, uniforms and CPU-solver vertex buffers are per frame
// slot (kFramesInFlight), each slot guarded by its two fences: writing frame N+1's indices never
// waits for frame N's draw.
//
// A frame is two calls, simulate() (substeps, normals, the early passes, LOD: the part that needs
// no target) and draw(target); frame() makes both. The demo drives it like this (per frame):
//     loop.simulate(view_params, swapchain extent)
//     acquire swapchain image i (semaphore `acquired[slot]`)
//     loop.draw(FrameTarget{image, view, format, extent, eUndefined, ePresentSrcKHR,
//                           acquired[slot], rendered[i]})
//     present image i waiting on rendered[i]
// Simulating before acquiring lets the frame's compute and LOD run while the window system still
// takes the last frame (on lavapipe under X without DRI3 every present is an XPutImage, and
// acquiring waits for the X server to finish it).
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "gpu/context.h"
#include "lod/camera_budget.h"
#include "scene/scene.h"
#include "sim/model.h"
#include "sim/session.h"
#include "view/sun_shadow.h"
#include "view/view_spec.h"

namespace pond::render {

// The image a frame is drawn into: an offscreen RenderTarget (render_target.h) or a swapchain
// image. The loop transitions it from `old_layout` (eUndefined: contents discarded, it is cleared)
// to the color-attachment layout and, at the end, to `final_layout` (ePresentSrcKHR for a
// swapchain, eTransferSrcOptimal for readback).
struct FrameTarget {
  vk::Image image;
  vk::ImageView view;
  vk::Format format = vk::Format::eUndefined;
  vk::Extent2D extent;
  vk::ImageLayout old_layout = vk::ImageLayout::eUndefined;
  vk::ImageLayout final_layout = vk::ImageLayout::eTransferSrcOptimal;
  vk::Semaphore wait_semaphore;    // optional: waited before color output (swapchain acquire)
  vk::Semaphore signal_semaphore;  // optional: signalled when the frame is drawn (present waits)
};

// What one frame shows and how far it advances.
struct FrameView {
  lod::Camera camera;             // width/height should match the target's extent
  double lod_tolerance_px = 1.0;  // 0 = the full mesh
  bool wireframe = false;         // overlay the LOD triangles
  std::int64_t steps = 1;         // simulation steps this frame (0 = frozen)
  bool wait = false;              // wait for the draw to finish (headless timing, readback)
  view::Effects effects;          // which of the picture's effects to draw
};

// The cost of one frame, by part. draw_ms covers recording and submitting, plus the GPU time when
// FrameView::wait was set.
struct FrameStats {
  double simulate_ms = 0;  // substeps + normals + making the positions visible to the CPU
  double lod_ms = 0;       // LOD build into the slot's mapped index buffer
  double draw_ms = 0;
  std::size_t triangles = 0;       // water triangles drawn
  std::size_t full_triangles = 0;  // 2 (rows-1)(cols-1)
  std::size_t land_triangles = 0;  // shore, islands, pool walls
};

// The per-frame values a drawable needs to draw into the loop's pass.
struct FrameInfo {
  const vk::raii::CommandBuffer& cmd;
  std::uint32_t slot;           // frame slot in [0, kFramesInFlight): index per-slot resources
  const float* view_proj;       // column-major 4x4, Vulkan clip space (y down, depth 0..1)
  std::array<float, 3> eye;
  vk::Extent2D extent;
  double seconds;               // simulated time: steps_done * dt
  const view::LightingSpec& lighting;  // the scene's, with the sun as set_sun() left it
  float pixel_scale = 1.0f;     // the target's pixels per frame pixel (the reflection's: 1/2)
};

// A second pipeline drawn in the same pass as the water (the wind tree). Its pipeline must be
// created for FrameLoop::color_format() and FrameLoop::kDepthFormat with dynamic rendering.
class PassDrawable {
 public:
  virtual ~PassDrawable() = default;
  // Before the frame's passes (in simulate(), before the early ones), with the slot's previous use
  // finished: write per-slot uniforms, etc. What the front end may change between simulate() and
  // draw() (the demo's panel) is read in the draw calls instead.
  virtual void prepare(const FrameInfo& /*frame*/) {}
  // Inside the pass (viewport, scissor set; depth test on): bind and draw.
  virtual void draw(const FrameInfo& frame) = 0;
  // Inside the planar reflection's pass (render/reflection_pass.h: kReflectionFormat, kDepthFormat;
  // frame.extent and frame.pixel_scale are the reflection's): draw mirrored about y = 0. Drawables
  // that are not above the water (the demo's panel) draw nothing.
  virtual void draw_reflected(const FrameInfo& /*frame*/) {}
  // Inside the pass, before the scene: opaque screen-space overlays (the demo's panel) that write
  // the nearest depth, so the scene's fragments behind them fail the depth test before they are
  // shaded (on llvmpipe the water's shading is most of what a pixel under the panel costs).
  virtual void draw_occluding(const FrameInfo& /*frame*/) {}
  // After prepare(): the bounding spheres (world) of what this drawable casts into the sun's shadow
  // map, which is fitted to them (render/shadow_pass.h). None: it casts nothing.
  virtual void add_shadow_casters(std::vector<view::ShadowCaster>& /*casters*/) const {}
  // Inside the shadow map's pass (depth only, kShadowFormat; frame.view_proj is the sun's
  // orthographic projection, frame.extent the map's size): draw the casters, depth only.
  virtual void draw_shadow(const FrameInfo& /*frame*/) {}
};

class FrameLoop {
 public:
  static constexpr std::uint32_t kFramesInFlight = 2;
  static constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;

  // Draws `session` (which must outlive the loop, as must the context; its queue must do
  // graphics). `color_format`: the format of the images frame() draws into (pipelines are built
  // for it). The land is built from the session's model now: a session given new constraints
  // needs a new loop.
  FrameLoop(const gpu::Context& ctx, sim::Session& session, vk::Format color_format);
  ~FrameLoop();
  FrameLoop(const FrameLoop&) = delete;
  FrameLoop& operator=(const FrameLoop&) = delete;

  // One frame, see the top of this file: simulate(view, target.extent), then draw(target).
  FrameStats frame(const FrameTarget& target, const FrameView& view);
  // The first half of a frame: waits for its slot, advances the session view.steps, computes the
  // normals, submits the passes before the main one and builds the LOD, all for `extent` (the
  // size of the target draw() will get). Stats: simulate, LOD, and the early passes' recording in
  // draw.
  FrameStats simulate(const FrameView& view, vk::Extent2D extent);
  // Whether simulate() ran and its frame is not drawn yet, with the session's water unchanged
  // since (a splash or an edit in between makes the next frame simulate again).
  bool simulated() const;
  // The second half: draws the simulated frame into `target` (rebuilding the LOD and the early
  // passes first if the target's size differs from the one simulate() was given). Throws InternalError without a
  // simulated frame. Stats: the whole frame's.
  FrameStats draw(const FrameTarget& target);
  // Waits until every submitted frame is drawn (before reading back, resizing, tearing down).
  void wait_idle() const;

  // A new direction toward the sun (normalized on use) for the next frames; the caller has
  // checked it (scene::check_sun).
  void set_sun(const std::array<double, 3>& toward_sun);
  void add_drawable(PassDrawable& drawable);     // drawn after the water (occluders before the scene), in insertion order

  const sim::Session& session() const;
  const scene::Scene& scene() const;             // the session's
  const sim::WaterModel& model() const;          // the session's
  vk::Format color_format() const;
  // The scene's camera, or a view of the whole pond when the scene has none.
  lod::Camera default_camera(int width, int height) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pond::render
