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
#include "app/bench/workloads.h"
#include "sim/contact.h"
#include "sim/cpu_solver.h"

namespace {

using namespace pond;

// The demo's grid with `count` bodies: pond bench's workload (app/bench/workloads.h).
sim::WaterModel pond_257(int count) { return bench::bodies_model(257, count); }

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
void finish(sim::CpuSolver&) {}
void finish(gpu::GpuSolver& s) { s.finish(); }

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
