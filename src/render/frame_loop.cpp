#include "render/frame_loop.h"

#include <chrono>
#include <cstring>
#include <optional>
#include <vector>

#include "core/errors.h"
#include "render/early_passes.h"
#include "render/frame_data.h"
#include "render/main_pass.h"
#include "render/pass_timestamps.h"
#include "render/render_layout.h"
#include "render/reflection_pass.h"
#include "render/shadow_pass.h"
#include "render/submerged_pass.h"
#include "render/visible_geometry.h"
#include "render/water_pipeline.h"
#include "render/water_source.h"
#include "view/frame_plan.h"
#include "view/frame_uniforms.h"
#include "view/view_projection.h"

namespace pond::render {
namespace {

double ms_since(std::chrono::steady_clock::time_point& t) {
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - t).count();
  t = now;
  return ms;
}

}  // namespace

struct FrameLoop::Impl {
  const gpu::Context& ctx;
  const scene::Scene scene;
  sim::Session& session;
  vk::Format color_format;
  EarlyPasses passes;  // before the main one
  WaterPipelines pipes;
  FrameRing frames;
  WaterSource water;
  VisibleGeometry geometry;
  PassTimestamps timestamps;  // each pass's GPU time, read at the frame's wait; "main" last
  std::vector<PassDrawable*> drawables;
  std::uint32_t next = 0;

  // What prepare() left for draw().
  struct Prepared {
    std::uint32_t slot = 0;
    FrameView view;
    lod::Camera camera;  // view.camera at the size the frame was prepared for
    std::array<float, 16> view_proj{};
    view::LightingSpec lighting;  // the scene's with the session's sun
    WaterSource::DrawBuffers water{};
    view::FramePlan plan;
    VisibleDraws draws;
    FrameStats stats;
    std::uint64_t state_revision = 0, generation = 0;
    PassSet passes;  // recorded before the main pass
  };
  std::optional<Prepared> prepared;
  PassSet last_passes;  // the last drawn frame's, the main pass among them

  Impl(const gpu::Context& c, const scene::Scene& s, sim::Session& drawn, const gpu::GpuSolvers* gpu,
       vk::Format format)
      : ctx(c), scene(s), session(drawn), color_format(format),
        passes(c, drawn.model()), pipes(create_water_pipelines(c, format, kDepthFormat, pass_bindings())),
        frames(c, *pipes.set_layout, pipes.set_bindings), water(c, drawn, gpu), geometry(c, drawn.model()),
        timestamps(c, kFramesInFlight, pass_names()), last_passes(timestamps.count(), false) {}

  std::vector<vk::DescriptorSetLayoutBinding> pass_bindings() const {
    std::vector<vk::DescriptorSetLayoutBinding> out;
    for (const FramePass* p : passes.list()) p->water_bindings(out);
    return out;
  }
  std::vector<std::string> pass_names() const {
    std::vector<std::string> out;
    for (const FramePass* p : passes.list()) out.emplace_back(p->name());
    out.emplace_back("main");
    return out;
  }
  std::size_t main_pass() const { return passes.list().size(); }  // its place among the timed

  FrameInfo info(const vk::raii::CommandBuffer& cmd, const Prepared& f) const {
    return {cmd, f.slot, f.view_proj.data(),
            {static_cast<float>(f.camera.eye[0]), static_cast<float>(f.camera.eye[1]), static_cast<float>(f.camera.eye[2])},
            {static_cast<std::uint32_t>(f.camera.width), static_cast<std::uint32_t>(f.camera.height)},
            session, f.lighting, water.bodies(), f.water.bodies};
  }
  FrameContext context(const Prepared& f, const FrameInfo& base) {
    return {f.slot, frames[f.slot], f.water, frames.placeholders(), f.plan, f.draws, geometry, pipes, drawables, base,
            timestamps};
  }

  // The frame's resources, camera, plan, land and uniforms at `extent`; the early passes into
  // `cmd` (begun); the LOD. The slot must be finished.
  void set_up(Prepared& f, vk::Extent2D extent, const vk::raii::CommandBuffer& cmd) {
    FrameData& d = frames[f.slot];
    const int w = static_cast<int>(extent.width), h = static_cast<int>(extent.height);
    f.camera = f.view.camera;
    f.camera.width = w, f.camera.height = h;
    f.view_proj = view::view_projection(f.camera, session.model());
    f.lighting = scene.lighting;
    f.lighting.sun = session.sun();
    const FrameInfo base = info(cmd, f);
    for (PassDrawable* p : drawables) p->prepare(base);
    std::vector<view::ShadowCaster> casters;
    for (const PassDrawable* p : drawables) p->add_shadow_casters(casters);
    f.plan = view::plan_frame({f.view.effects, casters, geometry.submerged_boxes(), f.view_proj, w, h, f.lighting.sun,
                               session.model().basin.floor_depth, session.model().basin.land_height});
    const vk::Extent2D mirror = f.plan.reflection ? reflection_extent(extent) : vk::Extent2D{0, 0};
    geometry.cull_land(f.slot, f.view_proj, w, h, f.plan.shadow_rects,
                       {static_cast<int>(mirror.width), static_cast<int>(mirror.height)}, f.draws);
    WaterFrame u = view::frame_uniforms({session.model(), f.lighting, f.camera, f.view_proj,
                                               f.water.stride, f.water.pitch, f.plan.shadow ? &*f.plan.shadow : nullptr});
    const FrameContext frame = context(f, base);
    WaterSetWrites pass_writes;  // what the passes bind into the water's set, and their lanes of u
    for (FramePass* p : passes.list()) {
      p->prepare(frame);
      p->bind_water(frame, pass_writes, u);
    }
    write_frame_set(ctx, d, *f.water.state, *f.water.normals, std::move(pass_writes.writes));
    std::memcpy(d.uniforms.mapped, &u, sizeof u);
    d.uniforms.flush(ctx);
    timestamps.begin_frame(cmd, f.slot);
    f.passes = passes.record(cmd, frame);
  }

  // The LOD of the positions sync() left on the host: the nodes the frame kept there (keep_on_host,
  // from the last frame's reads); where it needs others, it brings them through `fetch`, waiting.
  void build_lod(Prepared& f) {
    lod::NodePositions positions = water.positions();
    positions.fetch = water.fetch();
    geometry.build_water(f.slot, positions, water.tile_bounds(), f.camera, f.view_proj, f.view.lod_tolerance_px,
                         f.plan.shadow_rects, f.draws);
    water.keep_on_host(geometry.lod_reads());  // what the next frames' compute copies back
    f.stats.triangles = f.draws.water_triangles;
  }

  FrameStats prepare(const FrameView& view, vk::Extent2D extent) {
    Prepared f;
    f.slot = next;
    f.view = view;
    f.stats.full_triangles = geometry.full_triangles();
    f.stats.land_triangles = geometry.land_triangles();
    auto t = std::chrono::steady_clock::now();
    water.sync();  // the frame's one wait: for the last compute, which also finishes this slot's last use
    f.stats.wait_ms = ms_since(t);
    frames.finish(f.slot);
    timestamps.collect(f.slot);  // finished: its last frame's pass times are there to read
    f.water = water.prepare(f.slot);
    f.state_revision = session.state_revision();
    f.generation = session.solver_generation();
    set_up(f, extent, frames.begin_early(f.slot));
    frames.submit_early(f.slot);  // the device draws them while the CPU builds the LOD
    f.stats.draw_ms = ms_since(t);
    build_lod(f);
    f.stats.lod_ms = ms_since(t);
    prepared = std::move(f);
    return prepared->stats;
  }

  bool is_prepared() const {
    return prepared && prepared->state_revision == session.state_revision() &&
           prepared->generation == session.solver_generation();
  }

  FrameStats draw(const FrameTarget& target) {
    if (!is_prepared()) throw InternalError("FrameLoop::draw without a prepared frame");
    Prepared f = std::move(*prepared);
    prepared.reset();
    next = (f.slot + 1) % kFramesInFlight;
    auto t = std::chrono::steady_clock::now();
    const vk::raii::CommandBuffer& cmd = frames.begin_main(f.slot);
    if (static_cast<std::uint32_t>(f.camera.width) != target.extent.width ||
        static_cast<std::uint32_t>(f.camera.height) != target.extent.height) {
      frames.finish(f.slot);  // the window was resized between the halves: the early passes again
      set_up(f, target.extent, cmd);
      build_lod(f);
      f.stats.lod_ms += ms_since(t);
    }
    frames.ensure_depth(f.slot, target.extent);
    last_passes = f.passes;
    last_passes.push_back(true);  // the main pass
    {
      const PassTimestamps::Scope timed = timestamps.scope(cmd, f.slot, main_pass());
      record_main_pass(cmd, context(f, info(cmd, f)), target,
                       {.wireframe = f.view.wireframe, .reflections = f.plan.reflection, .caustics = f.plan.caustics,
                        .submerged = f.plan.submerged, .sky = f.lighting.sky});
    }
    frames.submit_main(f.slot, target);
    if (f.view.wait) {
      frames.finish(f.slot);
      timestamps.collect(f.slot);
    }
    f.stats.draw_ms += ms_since(t);
    return f.stats;
  }
};

FrameLoop::FrameLoop(const gpu::Context& ctx, const scene::Scene& scene, sim::Session& session,
                     const gpu::GpuSolvers* gpu, vk::Format color_format)
    : impl_(std::make_unique<Impl>(ctx, scene, session, gpu, color_format)) {}

FrameLoop::~FrameLoop() {
  if (!impl_) return;
  try {
    impl_->frames.finish_all();
  } catch (const vk::SystemError&) {  // a lost device: nothing runs any more
  }
}

FrameStats FrameLoop::frame(const FrameTarget& target, const FrameView& view) {
  impl_->prepare(view, target.extent);
  return impl_->draw(target);
}
FrameStats FrameLoop::prepare(const FrameView& view, vk::Extent2D extent) { return impl_->prepare(view, extent); }
bool FrameLoop::prepared() const { return impl_->is_prepared(); }
FrameStats FrameLoop::draw(const FrameTarget& target) { return impl_->draw(target); }
void FrameLoop::wait_idle() { impl_->frames.finish_all(); }
const PassTimestamps& FrameLoop::timestamps() const { return impl_->timestamps; }
void FrameLoop::add_drawable(PassDrawable& drawable) { impl_->drawables.push_back(&drawable); }

const sim::Session& FrameLoop::session() const { return impl_->session; }
const scene::Scene& FrameLoop::scene() const { return impl_->scene; }
const sim::WaterModel& FrameLoop::model() const { return impl_->session.model(); }
vk::Format FrameLoop::color_format() const { return impl_->color_format; }
lod::Camera FrameLoop::default_camera(int width, int height) const {
  return view::scene_camera(impl_->scene.camera, impl_->session.model(), width, height);
}
FramePass* FrameLoop::pass(std::string_view name) { return impl_->passes.find(name); }
PassSet FrameLoop::passes_recorded() const { return impl_->last_passes; }
bool FrameLoop::recorded(std::string_view name) const {
  const std::size_t p = impl_->timestamps.index_of(name);
  return p < impl_->last_passes.size() && impl_->last_passes[p];
}
CarriedPasses FrameLoop::carry_passes() {
  CarriedPasses out;
  for (FramePass* p : impl_->passes.list())
    if (std::any c = p->carry(); c.has_value()) out.emplace_back(p->name(), std::move(c));
  return out;
}
void FrameLoop::adopt_passes(CarriedPasses carried) {
  for (auto& [name, c] : carried)
    if (FramePass* p = impl_->passes.find(name)) p->adopt(std::move(c));
}
std::size_t FrameLoop::pass_targets() const {
  std::size_t made = 0;
  for (const FramePass* p : impl_->passes.list()) made += p->targets_made();
  return made;
}
std::span<const std::uint32_t> FrameLoop::lod_triangles() const { return impl_->geometry.lod_triangles(); }

}  // namespace pond::render
