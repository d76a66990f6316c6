// GPU solver speed on the device pond chooses (lavapipe here): node-steps per second at 256²,
// 512², 1024², exact and fast math; the cost of one dispatch (1,000 substeps of an 8x8 grid, one
// command buffer); and the scalar CPU backend on one thread at 1024² in the same run, for the
// ratio, also alternated with the GPU within one benchmark (BM_GpuVsCpuScalarRatio); the tile
// bounds' cost per frame (BM_GpuTileBoundsCost). Validation is off (it would measure the layer).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <vector>

#include "gpu/context.h"
#include "gpu/headless.h"
#include "gpu/gpu_solver.h"
#include "sim/cpu_solver.h"
#include "sim/model.h"
#include "scene/scene.h"

namespace {

using namespace pond;

// A square pond with a fixed shore, an island and a splash in the middle: every code path of a
// substep (free, fixed, borders) runs, the waves keep every node busy.
sim::WaterModel square_pond(int n, int substeps, sim::MathMode math) {
  scene::Scene s;
  s.grid.rows = s.grid.cols = n;
  s.physics.substeps = substeps;
  s.constraints.push_back({sim::NodeKind::fixed, n / 4, n / 4 + n / 16, n / 2, n / 2 + n / 16});
  s.perturbations.push_back({.step = 0, .row = n / 2.0, .col = n / 3.0, .radius = n / 32.0 + 1.0,
                             .amplitude = 1.0, .target = sim::PerturbTarget::velocity,
                             .mode = sim::PerturbMode::add});
  return sim::build_model(s, math);
}

// CPU seconds of the whole process (every thread: llvmpipe's workers included). On a machine
// shared with other jobs, node-steps per CPU second is the load-independent figure; wall-clock
// node-steps/s on a quiet machine is about that times the cores the workers keep busy.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Sets the "node-steps/cpu-s" counter from the process CPU time spent since `cpu0`.
void count_cpu(benchmark::State& state, double node_steps, double cpu0) {
  state.counters["node-steps/cpu-s"] = node_steps / (process_cpu_seconds() - cpu0);
}

const gpu::Context& context() {
  static const std::unique_ptr<gpu::Context> ctx = [] {
    const char* device = std::getenv("POND_BENCH_DEVICE");
    return std::make_unique<gpu::Context>(gpu::headless_options(device ? device : "", false));
  }();
  return *ctx;
}

void BM_GpuStep(benchmark::State& state, sim::MathMode math) {
  const int n = static_cast<int>(state.range(0));
  gpu::GpuSolver solver(context(), square_pond(n, 1, math));
  constexpr std::int64_t kSteps = 8;
  solver.advance(kSteps);  // warm-up: pipeline compiled, pages touched
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    solver.advance(kSteps);
    solver.finish();
  }
  const double node_steps = static_cast<double>(n) * n * kSteps * static_cast<double>(state.iterations());
  state.counters["node-steps/s"] = benchmark::Counter(node_steps, benchmark::Counter::kIsRate);
  count_cpu(state, node_steps, cpu0);
  state.SetLabel(context().device_name());
}
BENCHMARK_CAPTURE(BM_GpuStep, exact, sim::MathMode::exact)->Arg(256)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_GpuStep, fast, sim::MathMode::fast)->Arg(256)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();

// The host's copies of the state for the CPU twin (gpu/state_snapshots.h): the same steps with a
// copy every StateSnapshots::kSubsteps substeps (as pond runs) and with none, alternated in one
// benchmark so both see the same load; the counters are each half's node-steps per second.
void BM_GpuHostCopyCost(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  gpu::GpuSolver with(context(), square_pond(n, 1, sim::MathMode::exact));
  gpu::GpuSolver without(context(), square_pond(n, 1, sim::MathMode::exact));
  without.set_host_copy_interval(0);
  constexpr std::int64_t kSteps = gpu::StateSnapshots::kSubsteps;
  double t_with = 0, t_without = 0;
  using clock = std::chrono::steady_clock;
  for (gpu::GpuSolver* s : {&with, &without}) s->advance(8), s->finish();
  for (auto _ : state) {
    for (gpu::GpuSolver* s : {&with, &without}) {
      const auto t0 = clock::now();
      s->advance(kSteps);
      s->finish();
      s->host_snapshot();  // the host takes the copy, as a session does after each advance
      (s == &with ? t_with : t_without) += std::chrono::duration<double>(clock::now() - t0).count();
    }
  }
  const double node_steps = static_cast<double>(n) * n * kSteps * static_cast<double>(state.iterations());
  state.counters["with copies node-steps/s"] = node_steps / t_with;
  state.counters["without node-steps/s"] = node_steps / t_without;
  state.counters["cost %"] = 100.0 * (t_with - t_without) / t_without;
  state.SetLabel(context().device_name());
}
BENCHMARK(BM_GpuHostCopyCost)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

// 1,000 substeps of an 8x8 grid = 1,000 dispatches + barriers in one command buffer: the fixed
// cost of a dispatch (recording, submission amortized, the driver's launch, the barrier).
void BM_GpuDispatchOverhead(benchmark::State& state) {
  constexpr int kSubsteps = 1000;
  gpu::GpuSolver solver(context(), square_pond(8, kSubsteps, sim::MathMode::exact));
  solver.advance(1);
  for (auto _ : state) {
    solver.advance(1);
    solver.finish();
  }
  // Seconds per dispatch (printed with an SI prefix: "19u" = 19 microseconds).
  state.counters["s/dispatch"] = benchmark::Counter(static_cast<double>(state.iterations()) * kSubsteps,
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_GpuDispatchOverhead)->Unit(benchmark::kMillisecond)->UseRealTime();

// The reference for the ratio: the scalar CPU backend, one thread, 1024².
void BM_CpuScalarOneThread(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  sim::CpuSolver solver(square_pond(n, 1, sim::MathMode::exact), sim::Backend::scalar, 1);
  constexpr std::int64_t kSteps = 2;
  solver.advance(kSteps);
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) solver.advance(kSteps);
  const double node_steps = static_cast<double>(n) * n * kSteps * static_cast<double>(state.iterations());
  state.counters["node-steps/s"] = benchmark::Counter(node_steps, benchmark::Counter::kIsRate);
  count_cpu(state, node_steps, cpu0);
}
BENCHMARK(BM_CpuScalarOneThread)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();

// The target ratio measured robustly on a shared machine: GPU exact and CPU scalar (one thread)
// at 1024^2 alternate within every iteration (4 GPU steps, then 1 CPU step, each timed), so both see
// the same load over the run instead of whatever load each had in its own benchmark. Counters: the
// wall-clock ratio of node-steps/s (what the target asks), the ratio per process CPU second (the
// efficiency, independent of how many cores the 2 lavapipe workers get), and the cores the GPU
// phases used on average (2 on a quiet machine).
void BM_GpuVsCpuScalarRatio(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  gpu::GpuSolver gpu_solver(context(), square_pond(n, 1, sim::MathMode::exact));
  sim::CpuSolver cpu_solver(square_pond(n, 1, sim::MathMode::exact), sim::Backend::scalar, 1);
  constexpr std::int64_t kGpuSteps = 4, kCpuSteps = 1;
  gpu_solver.advance(kGpuSteps);
  cpu_solver.advance(kCpuSteps);
  using Clock = std::chrono::steady_clock;
  double gpu_wall = 0, gpu_cpu = 0, cpu_wall = 0, cpu_cpu = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    const double c0 = process_cpu_seconds();
    gpu_solver.advance(kGpuSteps);
    gpu_solver.finish();
    const auto t1 = Clock::now();
    const double c1 = process_cpu_seconds();
    cpu_solver.advance(kCpuSteps);
    const auto t2 = Clock::now();
    const double c2 = process_cpu_seconds();
    gpu_wall += std::chrono::duration<double>(t1 - t0).count();
    cpu_wall += std::chrono::duration<double>(t2 - t1).count();
    gpu_cpu += c1 - c0;
    cpu_cpu += c2 - c1;
  }
  const double gpu_steps = static_cast<double>(kGpuSteps), cpu_steps = static_cast<double>(kCpuSteps);
  state.counters["wall-ratio"] = (gpu_steps / gpu_wall) / (cpu_steps / cpu_wall);
  state.counters["cpu-s-ratio"] = (gpu_steps / gpu_cpu) / (cpu_steps / cpu_cpu);
  state.counters["gpu-cores"] = gpu_cpu / gpu_wall;
  state.counters["cpu-cores"] = cpu_cpu / cpu_wall;
}
BENCHMARK(BM_GpuVsCpuScalarRatio)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(5.0);

// The tile bounds' cost (GpuSolver::track_tile_bounds): frames of a drawn solver (one step, then
// the normals, which the bounds ride on), tracking off and on in two solvers of one scene,
// alternated within every iteration (which goes first alternates too) so both see the same load.
// Counters: the median milliseconds of a frame off and on (every frame timed on its own), wall
// clock and process CPU time (every thread's: llvmpipe's workers; less moved by other jobs on a
// shared machine), and their ratios.
// Args: the grid's side and the substeps of a frame's one step (the bounds come once a frame).
void BM_GpuTileBoundsCost(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const sim::WaterModel model = square_pond(n, static_cast<int>(state.range(1)), sim::MathMode::exact);
  gpu::GpuSolver off(context(), model, true), on(context(), model, true);
  on.track_tile_bounds(true);
  for (gpu::GpuSolver* s : {&off, &on}) {
    s->advance(8);  // warm-up: pipelines compiled, pages touched
    s->finish();
  }
  using Clock = std::chrono::steady_clock;
  std::vector<double> wall[2], cpu[2];  // [0] off, [1] on
  auto frame = [&](gpu::GpuSolver& s, int k) {
    const auto t0 = Clock::now();
    const double c0 = process_cpu_seconds();
    s.advance(1);
    s.finish();
    cpu[k].push_back(1e3 * (process_cpu_seconds() - c0));
    wall[k].push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  };
  bool on_first = false;
  for (auto _ : state) {
    if (on_first) frame(on, 1);
    frame(off, 0);
    if (!on_first) frame(on, 1);
    on_first = !on_first;
  }
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  state.counters["off-ms"] = median(wall[0]);
  state.counters["on-ms"] = median(wall[1]);
  state.counters["on/off"] = median(wall[1]) / median(wall[0]);
  state.counters["off-cpu-ms"] = median(cpu[0]);
  state.counters["on-cpu-ms"] = median(cpu[1]);
  state.counters["on/off-cpu"] = median(cpu[1]) / median(cpu[0]);
}
BENCHMARK(BM_GpuTileBoundsCost)->ArgsProduct({{257, 1025}, {1, 2}})->ArgNames({"side", "substeps"})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
