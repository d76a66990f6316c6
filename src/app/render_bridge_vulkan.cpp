// `pond render`: the frame loop (render/frame_loop.h) drawing into an offscreen image, read back and
// written as a PNG; median milliseconds per frame by part. It steps the session as the demo does:
// a frame draws the state the last steps left and then submits the next frame's steps, so the CPU
// waits once a frame, for those.
#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "app/cli_parse.h"
#include "app/render_bridge.h"
#include "core/errors.h"
#include "core/text.h"
#include "gpu/context.h"
#include "gpu/gpu_failure.h"
#include "gpu/gpu_solvers.h"
#include "render/body_drawable.h"
#include "render/frame_loop.h"
#include "core/png.h"
#include "render/render_target.h"
#include "render/tree_drawable.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "sim/session.h"
#include "view/view_projection.h"

namespace pond::app {
namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}


// Each effect the scene has on, timed against the same frame without it: frozen frames (the session
// not stepped) alternating off and on, so both halves see the same state and the same load; whole
// frames with the GPU's work (FrameView::wait). Only with --profile, after the picture is written: these
// frames overwrite it, and are not among the --frames N the picture and the medians count.
void print_effect_costs(render::FrameLoop& loop, const render::RenderTarget& target, render::FrameView view,
                        int frames) {
  if (frames < 2) return;
  const int pairs = std::min(frames, 40);
  view.wait = true;
  for (const view::EffectEntry& e : view::kEffects) {
    if (!(view.effects.*e.flag)) continue;
    // A frame of a configuration never drawn before also builds what it needs (lavapipe compiles
    // pipelines for tens of milliseconds): one untimed frame of each first, or with few pairs the
    // medians hold that and the cost comes out negative.
    for (bool with : {false, true}) {
      render::FrameView v = view;
      v.effects.*e.flag = with;
      loop.frame(target.frame_target(), v);
    }
    std::vector<double> on, off;
    for (int k = 0; k < pairs; ++k)
      for (bool with : {false, true}) {
        render::FrameView v = view;
        v.effects.*e.flag = with;
        const render::FrameStats s = loop.frame(target.frame_target(), v);
        (with ? on : off).push_back(s.wait_ms + s.lod_ms + s.draw_ms);
      }
    // A cost below the frames' noise can still come out negative: said so, not printed as a saving.
    const double cost = median(on) - median(off);
    char what[48] = "no cost above the noise";
    if (cost >= 0) std::snprintf(what, sizeof what, "%.3f ms per frame", cost);
    std::printf("effect %s: %s (with %.3f, without %.3f; medians of %d alternated frozen frames)\n", e.key, what,
                median(on), median(off), pairs);
  }
}

// Each pass's GPU time from timestamp queries in the frames drawn above (read as their slots came
// round again, so the last frame or two are not among them), or why the device has none.
void print_pass_times(const render::PassTimestamps& timestamps, const std::vector<std::vector<double>>& pass_ms) {
  if (!timestamps.supported()) {
    std::printf("GPU pass times: none, the device has no timestamps (%s)\n", timestamps.unsupported_reason().c_str());
    return;
  }
  bool any = false;
  for (const std::vector<double>& times : pass_ms) any = any || !times.empty();
  if (!any) {  // the frames' queries are read when their slot comes round again: too few frames
    std::printf("GPU pass times: none read back yet (give --frames 3 or more)\n");
    return;
  }
  std::printf("GPU pass times (timestamp queries, medians):");
  for (std::size_t p = 0; p < pass_ms.size(); ++p)
    if (!pass_ms[p].empty())
      std::printf(" %s %.3f ms (%zu frames);", timestamps.names()[p].c_str(),
                  median(pass_ms[p]), pass_ms[p].size());
  std::printf("\n");
}

// The frames of `scene` on `ctx` and the PNG of the last (a Vulkan failure reaches run_render).
int render_scene(const RenderOptions& o, const scene::Scene& scene, const gpu::Context& ctx) {
  const sim::SolverChoice solver = parse_solver(o.solver);
  gpu::GpuSolvers gpu_solvers(ctx);
  sim::SessionSpec spec = scene::session_spec(scene);
  // Said once the picture is written: a GPU solver that could not be made (and the CPU's in its
  // place) matters then; when the device is lost, the renderer fails too, and that is the one line.
  std::vector<std::string> notices;
  spec.notify = [&notices](const std::string& text) { notices.push_back(text); };
  sim::Session session(std::move(spec), solver, gpu_solvers.factory());
  session.track_tile_bounds(true);  // the LOD descends them instead of reading every node
  render::FrameLoop loop(ctx, scene, session, &gpu_solvers, render::RenderTarget::kFormat);
  std::optional<render::TreeDrawable> trees;  // the scene's wind trees, in the water's pass
  if (scene.tree) loop.add_drawable(trees.emplace(ctx, loop, *scene.tree));
  render::BodyDrawable bodies(ctx, loop);  // the scene's bodies, as the session moves them
  loop.add_drawable(bodies);
  render::FrameView view;
  view.camera = loop.default_camera(o.width, o.height);
  if (o.eye) view.camera.eye = *o.eye;
  if (o.target) view.camera.target = *o.target;
  if (o.fovy) view.camera.fovy_degrees = *o.fovy;
  view.camera = view::checked_camera(view.camera, o.eye ? "--eye" : "camera.eye", o.target ? "--target" : "camera.target");
  view.lod_tolerance_px = o.lod_tolerance.value_or(scene.view.lod_tolerance_px);
  view.wireframe = o.wireframe;
  view.effects = scene.view.effects;
  const std::int64_t steps_per_frame = scene.view.steps_per_frame;
  lod::validate(view.camera, view.lod_tolerance_px > 0 ? view.lod_tolerance_px : 1.0);

  render::RenderTarget target(ctx, o.width, o.height);
  using Clock = std::chrono::steady_clock;
  auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  session.advance(o.steps + steps_per_frame);  // what the first frame shows
  std::vector<double> total, simulate, wait, lod, draw;
  std::vector<std::vector<double>> pass_ms(loop.timestamps().count());  // the GPU's clock, frames as read
  std::uint64_t timed_frame = 0;
  render::FrameStats last;
  Clock::time_point start = Clock::now();
  for (int f = 0; f < o.frames; ++f) {
    session.catch_up_wind();  // the trees' wind clock is the simulated time
    last = loop.frame(target.frame_target(), view);
    const Clock::time_point drawn = Clock::now();
    if (f + 1 < o.frames) session.advance(steps_per_frame);  // the next frame's, submitted
    const Clock::time_point end = Clock::now();
    simulate.push_back(ms(drawn, end));
    wait.push_back(last.wait_ms);
    lod.push_back(last.lod_ms);
    draw.push_back(last.draw_ms);
    total.push_back(ms(start, end));
    start = end;
    if (const render::PassTimes& t = loop.timestamps().last(); t.frame != timed_frame) {
      timed_frame = t.frame;
      for (std::size_t p = 0; p < t.ran.size(); ++p)
        if (t.ran[p]) pass_ms[p].push_back(t.ms[p]);
    }
  }
  session.finite_state();
  const std::vector<std::uint8_t> rgba = target.read_rgba();
  if (o.validation && !ctx.validation_log().messages().empty())
    throw RuntimeError(std::to_string(ctx.validation_log().messages().size()) +
                       " Vulkan validation message(s), the first: " + ctx.validation_log().messages().front());
  pond::write_png(o.out, o.width, o.height, rgba);
  for (const std::string& n : notices) std::fprintf(stderr, "pond render: %s\n", n.c_str());

  const sim::WaterModel& m = session.model();
  char lod_text[64] = "full mesh";
  if (view.lod_tolerance_px > 0) std::snprintf(lod_text, sizeof lod_text, "LOD %g px", view.lod_tolerance_px);
  std::printf("rendered %d frame%s of a %d x %d grid at %dx%d on %s, %s solver, %" PRId64 " step%s per frame, %s\n",
              o.frames, o.frames == 1 ? "" : "s", m.rows, m.cols, o.width, o.height, ctx.device_name().c_str(),
              o.solver.c_str(), steps_per_frame, steps_per_frame == 1 ? "" : "s", lod_text);
  std::printf("ms per frame (median of %d): %.3f; its parts: simulate %.3f, wait %.3f, LOD %.3f, draw %.3f\n",
              o.frames, median(total), median(simulate), median(wait), median(lod), median(draw));
  std::printf("triangles: water %zu of %zu (%.1f%%), land %zu\n", last.triangles, last.full_triangles,
              last.full_triangles ? 100.0 * static_cast<double>(last.triangles) / static_cast<double>(last.full_triangles) : 0.0,
              last.land_triangles);
  if (trees) {
    const render::TreeDrawStats t = trees->stats();
    std::printf("tree: %zu instance%s of %zu vertices (%s), wind %g at %g deg, %g s of wind\n", t.instances,
                t.instances == 1 ? "" : "s", t.skeleton_vertices,
                scene.tree->draw == tree::TreeDraw::lines ? "lines" : "tubes", scene.wind.strength,
                scene.wind.direction_deg, session.wind().time());
  }
  if (bodies.drawn() > 0)
    std::printf("bodies: %zu drawn, %zu triangles\n", bodies.drawn(), bodies.triangles());
  if (o.profile) {
    print_pass_times(loop.timestamps(), pass_ms);
    print_effect_costs(loop, target, view, o.frames);
  }
  std::printf("steps done %" PRId64 "\nwrote %s\n", session.steps_done(), escaped(o.out).c_str());
  return 0;
}

}  // namespace

// A lost device or memory it cannot allocate ends the command with one line and nothing written.
int run_render(const RenderOptions& o) {
  const scene::Scene scene = scene::load_scene(o.scene);
  const gpu::Context ctx(gpu::ContextOptions{.device = o.device, .validation = o.validation});
  render::check_target_size(ctx, o.width, o.height, render::RenderTarget::kFormat);
  return gpu::guard_gpu(ctx, "while rendering", [&] { return render_scene(o, scene, ctx); });
}

}  // namespace pond::app
