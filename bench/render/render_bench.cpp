// ms per frame of the frame loop at 1280x720 on a rippled pond (several splashes, then 200 steps),
// GPU solver, 1 step per frame, each frame waited for: LOD at 1 px vs the full mesh, 129^2 and
// 257^2. Counters: the parts (simulate = substeps + normals + positions to the CPU; LOD; draw =
// record + submit + GPU) and the triangles drawn. Run from any directory; set XDG_RUNTIME_DIR.
//   render_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "gpu/gpu_solvers.h"
#include "render/frame_loop.h"
#include "render/render_target.h"
#include "scene/scene.h"
#include "scene/session_spec.h"

namespace {

using namespace pond;

std::string rippled_scene(int n) {
  const double s = (n - 1) / 128.0;  // splash positions scale with the grid
  auto splash = [&](int step, double r, double c, double radius, double amp) {
    return "{\"step\": " + std::to_string(step) + ", \"row\": " + std::to_string(r * s) + ", \"col\": " +
           std::to_string(c * s) + ", \"radius\": " + std::to_string(radius) + ", \"amplitude\": " +
           std::to_string(amp) + "}";
  };
  return "{\"grid\": {\"rows\": " + std::to_string(n) + ", \"cols\": " + std::to_string(n) +
         "}, \"constraints\": [{\"kind\": \"fixed\", \"rows\": [" + std::to_string(int(70 * s)) + ", " +
         std::to_string(int(82 * s)) + "], \"cols\": [" + std::to_string(int(80 * s)) + ", " +
         std::to_string(int(95 * s)) + "]}], \"perturbations\": [" + splash(0, 40, 40, 3, 1.5) + ", " +
         splash(30, 90, 50, 2, 1.0) + ", " + splash(60, 50, 100, 2.5, -1.2) + ", " + splash(120, 100, 100, 2, 1.0) +
         ", " + splash(150, 20, 90, 2, 0.8) + "]}";
}

struct Fixture {
  gpu::Context ctx{gpu::ContextOptions{}};
  gpu::GpuSolvers solvers{ctx};
  std::map<int, scene::Scene> scenes;
  std::map<int, std::unique_ptr<sim::Session>> sessions;  // before the loops that draw them
  std::map<int, std::unique_ptr<render::FrameLoop>> loops;
  render::RenderTarget target{ctx, 1280, 720};

  render::FrameLoop& loop(int n) {
    auto& l = loops[n];
    if (!l) {
      auto& s = sessions[n];
      const scene::Scene& scene = scenes[n] = scene::parse_scene(rippled_scene(n), "bench");
      s = std::make_unique<sim::Session>(scene::session_spec(scene), sim::SolverChoice{}, solvers.factory());
      s->advance(200);
      l = std::make_unique<render::FrameLoop>(ctx, scene, *s, &solvers, render::RenderTarget::kFormat);
    }
    return *l;
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void BM_Frame(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double tolerance = static_cast<double>(state.range(1));
  render::FrameLoop& loop = fixture().loop(n);
  render::FrameView view;
  view.camera = loop.default_camera(1280, 720);
  view.lod_tolerance_px = tolerance;
  view.wait = true;
  sim::Session& session = *fixture().sessions[n];
  double wait_ms = 0, lod_ms = 0, draw_ms = 0, tris = 0, full = 0;
  for (auto _ : state) {
    const render::FrameStats s = loop.frame(fixture().target.frame_target(), view);
    session.advance(1);  // the next frame's step, submitted; the next frame waits for it
    wait_ms += s.wait_ms;
    lod_ms += s.lod_ms;
    draw_ms += s.draw_ms;
    tris += static_cast<double>(s.triangles);
    full = static_cast<double>(s.full_triangles);
  }
  const double k = static_cast<double>(state.iterations());
  state.counters["wait_ms"] = wait_ms / k;
  state.counters["lod_ms"] = lod_ms / k;
  state.counters["draw_ms"] = draw_ms / k;
  state.counters["frame_ms"] = (wait_ms + lod_ms + draw_ms) / k;
  state.counters["triangles"] = tris / k;
  state.counters["full_triangles"] = full;
  state.SetLabel(std::to_string(n) + "^2, " + (tolerance > 0 ? "LOD " + std::to_string(int(tolerance)) + " px" : "full mesh"));
}
BENCHMARK(BM_Frame)
    ->ArgsProduct({{129, 257}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

}  // namespace

BENCHMARK_MAIN();
