#pragma once
// The frame loop of pond, shared by `pond render` (offscreen image) and the windowed demo
// (swapchain image). It draws the simulation session it is given, read only: the front end steps
// the session (GPU compute is submitted, not waited for) and the loop draws the state its last
// change left. It only orders the frame's parts and submits them:
//
//   prepare(): the frame's one wait, for the last compute (render/water_source.h: sync() leaves the
//     displacements, tile bounds and bodies on the host) -> the frame's resources
//     (render/frame_data.h), its camera, plan (view/frame_plan.h: passes, the sun's shadow map) and
//     uniforms (view/frame_uniforms.h) -> the passes before the main one, recorded and submitted
//     (render/early_passes.h: caustics, foam, shadow map, reflection, submerged layer) -> the
//     visible geometry (render/visible_geometry.h: the LOD of the positions on the host, culled,
//     streamed into the frame's index buffers) while the device draws those passes
//   draw(target): the main pass (render/main_pass.h) into the caller's image, submitted
//
// The LOD is built from the very state the frame draws (the positions the last submission left on
// the host), so its tau bound holds for the drawn surface exactly. On any device the CPU waits
// once a frame, on the compute it submitted at the end of the frame before, whose fence also
// covers that frame's draw (submission order); the frame's own fences are only polled.
//
// The demo drives it like this (per frame): input -> session edits (splashes are dispatches);
// loop.prepare(view, swapchain extent); acquire; loop.draw(target); present; session.advance(steps)
// (after presenting, so the compute overlaps the window system's work).
#include <any>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gpu/context.h"
#include "gpu/gpu_solvers.h"
#include "lod/camera_budget.h"
#include "render/frame_pass.h"
#include "render/frame_target.h"
#include "render/pass_timestamps.h"
#include "render/pass_drawable.h"
#include "scene/scene.h"
#include "sim/session.h"
#include "view/view_spec.h"

namespace pond::render {

// What one frame shows.
struct FrameView {
  lod::Camera camera;             // width/height should match the target's extent
  double lod_tolerance_px = 1.0;  // 0 = the full mesh
  bool wireframe = false;         // overlay the LOD triangles
  bool wait = false;              // wait for the frame's draw (headless timing by frame, readback)
  view::Effects effects;          // which of the picture's effects to draw
};

// The cost of one frame's parts on the CPU. draw_ms covers recording and submitting, plus the GPU
// time when FrameView::wait was set.
struct FrameStats {
  double wait_ms = 0;   // the host's wait for the last compute (and the positions made visible)
  double lod_ms = 0;    // the LOD and the culling into the slot's index buffers
  double draw_ms = 0;   // the rest: the frame's setup, recording and submitting its passes
  std::size_t triangles = 0;       // water triangles of the LOD (before culling)
  std::size_t full_triangles = 0;  // 2 (rows-1)(cols-1)
  std::size_t land_triangles = 0;  // shore, islands, pool walls
};

// What a loop's passes carry over to a new loop, by pass name.
using CarriedPasses = std::vector<std::pair<std::string, std::any>>;

class FrameLoop {
 public:
  // Draws `session` (which must outlive the loop, as must the context and `gpu`, what made its GPU
  // solvers: null when it has none) as `scene` shows it (its view, lighting and camera; copied).
  // `color_format`: the format of the images draw() gets (pipelines are built for it). The land is
  // built from the session's model now: a session given new constraints needs a new loop. The
  // session is not const: the loop never changes its state, but reading it waits (prepare()).
  FrameLoop(const gpu::Context& ctx, const scene::Scene& scene, sim::Session& session,
            const gpu::GpuSolvers* gpu, vk::Format color_format);
  ~FrameLoop();
  FrameLoop(const FrameLoop&) = delete;
  FrameLoop& operator=(const FrameLoop&) = delete;

  // One frame: prepare(view, target.extent), then draw(target).
  FrameStats frame(const FrameTarget& target, const FrameView& view);
  // The first half of a frame, for a target of `extent` (see the top of this file).
  FrameStats prepare(const FrameView& view, vk::Extent2D extent);
  // Whether prepare() ran and its frame is not drawn yet, with the session's water unchanged since
  // (a splash or an edit in between makes the next frame prepare again).
  bool prepared() const;
  // The second half: the prepared frame into `target` (prepared again first if the target's size
  // differs from the one prepare() was given). InternalError without a prepared frame.
  FrameStats draw(const FrameTarget& target);
  // Each pass's GPU time (timestamp queries) of the last frame whose slot was read: a frame drawn
  // with FrameView::wait is read at once, any other when its slot is prepared again.
  const PassTimestamps& timestamps() const;
  // Waits until every submitted frame is drawn (before reading back, resizing, tearing down).
  void wait_idle();

  void add_drawable(PassDrawable& drawable);  // drawn after the water (occluders before the scene), in insertion order

  const sim::Session& session() const;
  const scene::Scene& scene() const;      // as given
  const sim::WaterModel& model() const;   // the session's
  vk::Format color_format() const;
  // The scene's camera, or a view of the whole pond when the scene has none.
  lod::Camera default_camera(int width, int height) const;
  // The pass before the main one named `name` (FramePass::name; null: none), for tests and tools.
  FramePass* pass(std::string_view name);
  // What the passes hand a new loop of the same session (FramePass::carry: the foam), and the new
  // loop taking it before its first frame, so that it goes on from the old one's.
  CarriedPasses carry_passes();
  void adopt_passes(CarriedPasses carried);
  // Which passes the last drawn frame recorded (the main pass and those its plan had), whether or
  // not the device has timestamps to time them: by place in timestamps().names(), and by name.
  PassSet passes_recorded() const;
  bool recorded(std::string_view name) const;
  // How many images and buffers the passes before the main one have made so far, over every frame
  // slot (the caustics map, the reflection's and the submerged layer's two images, the shadow map,
  // the foam's buffers): none while every effect is off. For tests and tools.
  std::size_t pass_targets() const;
  // The last prepared frame's LOD triangles before culling (node indices; empty for the full mesh).
  std::span<const std::uint32_t> lod_triangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pond::render
