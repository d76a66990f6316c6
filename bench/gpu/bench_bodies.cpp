// What 8 and 64 bodies (two of them dragged spheres, the rest floating) cost a step of the 257x257 pond, every
// contact included (water, each other, the land): the same scene with and without them, alternated
// within every iteration (so a shared machine's load falls on both alike), on the CPU's best
// backend (all cores) and on the GPU solver (the device pond chooses, validation off). Counter
// "cost": time with bodies / time without - 1 (the targets: at most 0.2 for 8, 0.5 for 64); "cpu cost": the same
// with the process's CPU time (all its threads: on a CPU device such as lavapipe, the "GPU"'s
// work too). And the CPU's contact pass alone.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <memory>

#include "gpu/context.h"
#include "gpu/gpu_solver.h"
#include "gpu/headless.h"
#include "scene/scene.h"
#include "sim/contact.h"
#include "sim/cpu_solver.h"

namespace {

using namespace pond;

// The demo's grid: an island, a splash, and `count` bodies when count > 0: two spheres dragged
// across, the rest floating balls of radius 2 to 3 and densities 0.3 to 0.9 in rows of 8 across
// the pond, neighbours heading at each other (they collide within some 50 steps, then drift on the
// waves). 64 is a scene's most.
sim::WaterModel pond_257(int count) {
  scene::Scene s;
  s.grid.rows = s.grid.cols = 257;
  s.physics.rest_ratio = 0.95;
  s.constraints.push_back({sim::NodeKind::fixed, 60, 80, 150, 175});
  s.perturbations.push_back({.step = 0, .row = 128, .col = 90, .radius = 4, .amplitude = 1,
                             .target = sim::PerturbTarget::velocity, .mode = sim::PerturbMode::add});
  if (count == 0) return sim::build_model(s);
  for (int k = 0; k < 2; ++k) {
    sim::BodySpec b;
    b.motion = sim::BodyMotion::kinematic;
    b.radius = 3.0;
    b.path = {{0, {20.0, 0.5, 30.0 + 50 * k}}, {4000, {236.0, 0.5, 40.0 + 50 * k}}};
    s.bodies.push_back(b);
  }
  for (int k = 0; k < count - 2; ++k) {
    const int col = k % 8, row = k / 8;
    sim::BodySpec b;
    b.radius = 2.0 + 0.125 * (k % 9);
    b.density = 0.3 + 0.075 * (k % 9);
    b.position = {24.0 + 26 * col, col % 3 == 0 ? 3.5 : 0.0, 100.0 + 18 * row};
    b.velocity = {col % 2 == 0 ? 0.5 : -0.5, 0.0, 0.05 * (row % 3 - 1)};
    s.bodies.push_back(b);
  }
  return sim::build_model(s);
}

const gpu::Context& context() {
  static const std::unique_ptr<gpu::Context> ctx = [] {
    const char* device = std::getenv("POND_BENCH_DEVICE");
    return std::make_unique<gpu::Context>(gpu::headless_options(device ? device : "", false));
  }();
  return *ctx;
}

// The CPU time of the whole process (every thread), in seconds.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Alternates `steps` steps of `plain` and of `bodies` per iteration; counters: each one's ms per
// step and the bodies' cost, in real and in CPU time.
// The steps done: the CPU solver's return done, the GPU solver's are only submitted.
void finish(const sim::CpuSolver&) {}
void finish(const gpu::GpuSolver& s) { s.finish(); }

template <class Solver>
void alternate(benchmark::State& state, Solver& plain, Solver& bodies, std::int64_t steps) {
  plain.advance(steps);
  bodies.advance(steps);
  using Clock = std::chrono::steady_clock;
  double plain_s = 0, bodies_s = 0, plain_cpu = 0, bodies_cpu = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    const double c0 = process_cpu_seconds();
    plain.advance(steps);
    finish(plain);
    const auto t1 = Clock::now();
    const double c1 = process_cpu_seconds();
    bodies.advance(steps);
    finish(bodies);
    const auto t2 = Clock::now();
    const double c2 = process_cpu_seconds();
    plain_s += std::chrono::duration<double>(t1 - t0).count();
    bodies_s += std::chrono::duration<double>(t2 - t1).count();
    plain_cpu += c1 - c0;
    bodies_cpu += c2 - c1;
  }
  const double n = static_cast<double>(state.iterations() * steps);
  state.counters["ms/step"] = 1e3 * plain_s / n;
  state.counters["ms/step bodies"] = 1e3 * bodies_s / n;
  state.counters["cost"] = bodies_s / plain_s - 1.0;
  state.counters["cpu cost"] = bodies_cpu / plain_cpu - 1.0;
}

void BM_BodiesCostCpu(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  sim::CpuSolver plain(pond_257(0), sim::best_backend(), 0), bodies(pond_257(count), sim::best_backend(), 0);
  alternate(state, plain, bodies, 8);
  state.SetLabel(plain.engine());
}
BENCHMARK(BM_BodiesCostCpu)->Arg(8)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

// The contact pass alone (all the bodies in the water after 300 steps), one thread: what it
// adds to each substep of the CPU solver, next to BM_BodiesCostCpu's step time.
void BM_ContactPassCpu(benchmark::State& state) {
  const sim::WaterModel model = pond_257(static_cast<int>(state.range(0)));
  sim::CpuSolver solver(model, sim::best_backend(), 0);
  solver.advance(300);
  sim::WaterState water = solver.state();
  std::int64_t step = 300;
  const float reach = sim::horizontal_reach(water);
  for (auto _ : state) sim::resolve_contacts(water, model, step++, 0, reach);
}
BENCHMARK(BM_ContactPassCpu)->Arg(8)->Arg(64)->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_BodiesCostGpu(benchmark::State& state) {
  gpu::GpuSolver plain(context(), pond_257(0)), bodies(context(), pond_257(static_cast<int>(state.range(0))));
  alternate(state, plain, bodies, 16);
  state.SetLabel(context().device_name());
}
BENCHMARK(BM_BodiesCostGpu)->Arg(8)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

}  // namespace

BENCHMARK_MAIN();
