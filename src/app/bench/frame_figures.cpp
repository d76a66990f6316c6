#include "app/bench/frame_figures.h"

#include <nlohmann/json.hpp>

#include "core/process_cpu.h"
#include "gpu/gpu_solvers.h"
#include "render/body_drawable.h"
#include "render/frame_loop.h"
#include "render/render_target.h"
#include "render/tree_drawable.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "sim/session.h"

namespace pond::bench {
namespace {

// scenes/demo_257_bodies.json with its positions scaled from 257² to side².
std::string frame_scene_json(int side) {
  const double s = (side - 1) / 256.0;
  using nlohmann::json;
  json bodies = json::array();
  bodies.push_back({{"radius", 4.0}, {"motion", "kinematic"},
                    {"path", {{0, 40 * s, 0.5, 100 * s}, {2000, 220 * s, 0.5, 100 * s}}}});
  for (const auto& [x, z] : {std::pair{60, 60}, {100, 180}, {140, 80}, {180, 200}, {200, 60}, {70, 220}, {120, 150}})
    bodies.push_back({{"radius", 3.0}, {"motion", "floating"}, {"mass", 30.0}, {"position", {x * s, 2.5, z * s}}});
  const json scene = {
      {"grid", {{"rows", side}, {"cols", side}}},
      {"physics", {{"substeps", 2}}},
      {"constraints", {{{"kind", "fixed"}, {"rows", {int(120 * s), int(136 * s)}}, {"cols", {int(150 * s), int(170 * s)}}}}},
      {"perturbations", {{{"step", 0}, {"row", 60 * s}, {"col", 80 * s}, {"radius", 2.0}, {"amplitude", 1.0}},
                         {{"step", 0}, {"row", 190 * s}, {"col", 200 * s}, {"radius", 2.0}, {"amplitude", 0.8}}}},
      {"view", {{"steps_per_frame", 1}, {"lod_tolerance", 1.0}}},
      {"tree", {{"depth", 8}, {"seed", 1}, {"height", 14.0}, {"draw", "tubes"}, {"leaves", true}}},
      {"wind", {{"strength", 4}, {"direction_deg", 20}, {"ripples", true}}},
      {"bodies", bodies}};
  return scene.dump();
}

}  // namespace

void measure_frame(const gpu::Context& ctx, const Plan& plan, Progress& progress, Report& report) {
  const int side = plan.frame_grid(), width = plan.frame_width(), height = plan.frame_height();
  const std::string where = std::to_string(side) + "², tree, 8 bodies, " + std::to_string(width) + "x" +
                            std::to_string(height);
  progress.show("frame, " + where + " (setting up)");
  const scene::Scene scene = scene::parse_scene(frame_scene_json(side), "pond bench's frame scene");
  render::check_target_size(ctx, width, height, render::RenderTarget::kFormat);
  gpu::GpuSolvers solvers(ctx);
  sim::Session session(scene::session_spec(scene), sim::SolverChoice{}, solvers.factory());
  session.track_tile_bounds(true);
  render::FrameLoop loop(ctx, scene, session, &solvers, render::RenderTarget::kFormat);
  render::TreeDrawable tree(ctx, loop, *scene.tree);
  loop.add_drawable(tree);
  render::BodyDrawable bodies(ctx, loop);
  loop.add_drawable(bodies);
  render::RenderTarget target(ctx, width, height);
  render::FrameView on;
  on.camera = loop.default_camera(width, height);
  on.lod_tolerance_px = scene.view.lod_tolerance_px;
  on.wait = true;  // each frame whole: its CPU parts and the GPU's, and its timestamps read at once
  render::FrameView off = on;
  off.effects = view::Effects::none();
  session.advance(40);  // the splashes spread, the balls settle a little

  Figure all = make_figure("frame.all_effects", "frame, every effect on, " + where, "ms", false);
  Figure none = make_figure("frame.no_effects", "frame, every effect off, " + where, "ms", false);
  // Each frame with the step after it, from the end of the one before: every thread's CPU time
  // (core/process_cpu.h), the driver's included; on a CPU device, that over the cores is the frame's floor.
  Figure all_cpu = make_figure("frame.cpu.all_effects", "CPU time of that frame, every effect on, all threads", "ms", false);
  Figure none_cpu = make_figure("frame.cpu.no_effects", "CPU time of that frame, every effect off, all threads", "ms", false);
  std::vector<Figure> passes(loop.timestamps().count());
  for (std::size_t p = 0; p < passes.size(); ++p) {
    const char* name = loop.timestamps().names()[p].c_str();
    passes[p] = make_figure(std::string("frame.gpu.") + name, std::string("GPU time of the ") + name +
                 " pass, every effect on (timestamps)", "ms", false);
  }
  const int warm = 2;
  core::CpuLaps cpu;
  for (int k = 0; k < warm + plan.frame_count(); ++k) {
    progress.show("frame, " + where + ", " + std::to_string(k + 1) + " of " + std::to_string(warm + plan.frame_count()));
    for (const bool effects : {true, false}) {  // alternated, so a shared machine's load falls on both alike
      session.catch_up_wind();
      const render::FrameStats s = loop.frame(target.frame_target(), effects ? on : off);
      session.advance(1);  // the next frame's step, submitted; the next frame waits for it
      const double cpu_ms = cpu.lap();
      if (k < warm) continue;
      (effects ? all : none).samples.push_back(s.wait_ms + s.lod_ms + s.draw_ms);
      (effects ? all_cpu : none_cpu).samples.push_back(cpu_ms);
      const render::PassTimes& t = loop.timestamps().last();
      if (effects)
        for (std::size_t p = 0; p < passes.size(); ++p)
          if (t.ran[p]) passes[p].samples.push_back(t.ms[p]);
    }
  }
  loop.wait_idle();
  report.add(std::move(all));
  report.add(std::move(none));
  report.add(std::move(all_cpu));
  report.add(std::move(none_cpu));
  if (!loop.timestamps().supported()) {
    report.notes.push_back("no per-pass GPU times: the device has no timestamps (" +
                           loop.timestamps().unsupported_reason() + "); the frames ran without them");
    return;
  }
  for (Figure& f : passes)
    if (!f.samples.empty()) report.add(std::move(f));
}

}  // namespace pond::bench
