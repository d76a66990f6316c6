// Node-steps per second of the CPU solver: every backend at 50^2, 256^2 and 1024^2, one thread and
// all threads, exact and fast math; and the machine's copy bandwidth measured in the same run, the
// memory-bound ceiling (a substep reads and writes 24 bytes of state per node); and the cost of
// the tile bounds (BM_TileBounds, and as a paired ratio: BM_TileBoundsPaired).
//
//   build/bench/sim/bench_solver --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include "sim/aligned_buffer.h"
#include "sim/cpu_solver.h"
#include "sim/water_spec.h"
#include "tile_row_alone.h"

namespace {
using namespace pond::sim;

// A rippled square pond: a fixed shore and several splashes, so every node has a non-trivial state.
WaterModel rippled_model(int size, MathMode math, int substeps = 1) {
  WaterSpec s;
  s.grid.rows = s.grid.cols = size;
  s.physics.substeps = substeps;
  for (int k = 0; k < 5; ++k) {
    Perturbation p;
    p.row = size * (0.2 + 0.15 * k);
    p.col = size * (0.7 - 0.1 * k);
    p.radius = 2.0;
    p.amplitude = 0.5;
    s.perturbations.push_back(p);
  }
  return build_model(s, math);
}

// Whether `state` was skipped because this CPU cannot run `backend`'s kernels.
bool skipped_without(Backend backend, benchmark::State& state) {
  if (cpu_supports(backend)) return false;
  state.SkipWithError("backend not supported by this CPU");
  return true;
}

// Args: backend, size, threads, math (0 exact, 1 fast) and, where given, whether the kernels emit
// the tile bounds (sim/tile_bounds.h) and the substeps of a step. Each iteration is one advance(1):
// a frame of one step.
void run_solver(benchmark::State& state, bool tiles, int substeps = 1) {
  const auto backend = static_cast<Backend>(state.range(0));
  const int size = static_cast<int>(state.range(1));
  const int threads = static_cast<int>(state.range(2));
  const auto math = static_cast<MathMode>(state.range(3));
  if (skipped_without(backend, state)) return;
  CpuSolver solver(rippled_model(size, math, substeps), backend, threads);
  solver.advance(20);  // the splashes spread
  solver.track_tile_bounds(tiles);
  for (auto _ : state) solver.advance(1);
  const double nodes = double(size) * size;
  state.counters["node_steps_per_s"] =
      benchmark::Counter(nodes * double(state.iterations()), benchmark::Counter::kIsRate);
  state.SetLabel(std::string(backend_name(backend)) + " x" + std::to_string(solver.threads()) +
                 (math == MathMode::exact ? " exact" : " fast") + (tiles ? " tiles" : "") +
                 (substeps > 1 ? " x" + std::to_string(substeps) + " substeps" : ""));
}
void BM_Solver(benchmark::State& state) { run_solver(state, false); }
void BM_TileBounds(benchmark::State& state) {
  run_solver(state, state.range(4) != 0, static_cast<int>(state.range(5)));
}

void solver_args(benchmark::internal::Benchmark* b) {
  const int all = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int size : {50, 256, 1024})
    for (int backend : {0, 1, 2, 3})
      for (int threads : {1, all})
        for (int math : {0, 1}) {
          if (threads == all && all == 1 && threads != 1) continue;
          b->Args({backend, size, threads, math});
        }
}
BENCHMARK(BM_Solver)->Apply(solver_args)->ArgNames({"backend", "size", "threads", "fast"})
    ->Unit(benchmark::kMicrosecond)->UseRealTime()->MinTime(0.3);

// The cost of the tile bounds: every backend at 1024^2 and 256^2, exact math, one thread and all
// threads, without and with them, in a frame of one substep (every substep emits them) and of two
// (the demo scenes'; the last one emits them) (docs/perf.md).
void tile_args(benchmark::internal::Benchmark* b) {
  const int all = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int substeps : {1, 2})
    for (int size : {256, 1024})
      for (int backend : {0, 1, 2, 3})
        for (int threads : {1, all})
          for (int tiles : {0, 1}) b->Args({backend, size, threads, 0, tiles, substeps});
}
BENCHMARK(BM_TileBounds)->Apply(tile_args)->ArgNames({"backend", "size", "threads", "fast", "tiles", "substeps"})
    ->Unit(benchmark::kMicrosecond)->UseRealTime()->MinTime(0.3);

// The tile bounds' cost as a paired ratio: two solvers in the same state, one emitting the bounds,
// advanced one frame each in turn (which goes first alternates), each frame timed on its own.
// A noisy host slows both frames of a pair alike. Where the two solvers' arrays lie in memory can
// alone make one step several per cent faster than the other, so the one that emits the bounds
// changes every kRolePairs pairs: `cost_a_pct` and `cost_b_pct` are the medians over the pairs of
// (frame with bounds / frame without) - 1, in percent, with `a` and with `b` emitting them, and
// `cost_pct` their geometric mean, in which a placement's factor cancels. Args: backend, size,
// substeps.
void BM_TileBoundsPaired(benchmark::State& state) {
  const auto backend = static_cast<Backend>(state.range(0));
  const int size = static_cast<int>(state.range(1));
  if (skipped_without(backend, state)) return;
  const WaterModel model = rippled_model(size, MathMode::exact, static_cast<int>(state.range(2)));
  CpuSolver a(model, backend, 1), b(model, backend, 1);
  a.advance(20);
  b.advance(20);
  constexpr std::size_t kRolePairs = 16;
  using Clock = std::chrono::steady_clock;
  const auto frame = [](CpuSolver& solver) {
    const auto t0 = Clock::now();
    solver.advance(1);
    return std::chrono::duration<double>(Clock::now() - t0).count();
  };
  std::vector<double> by_role[2];
  for (std::size_t n = 0; state.KeepRunning(); ++n) {
    const int role = static_cast<int>(n / kRolePairs % 2);  // 0: `a` emits the bounds
    if (n % kRolePairs == 0) {
      a.track_tile_bounds(role == 0);
      b.track_tile_bounds(role == 1);
    }
    CpuSolver& tiled = role == 0 ? a : b;
    CpuSolver& plain = role == 0 ? b : a;
    const bool plain_first = n % 2 == 0;
    const double first = frame(plain_first ? plain : tiled), second = frame(plain_first ? tiled : plain);
    by_role[role].push_back(plain_first ? second / first : first / second);
  }
  const auto median = [](std::vector<double>& r) {
    if (r.empty()) return std::nan("");  // too short a run for both halves
    std::sort(r.begin(), r.end());
    return r[r.size() / 2];
  };
  const double with_a = median(by_role[0]), with_b = median(by_role[1]);
  state.counters["cost_pct"] = 100.0 * (std::sqrt(with_a * with_b) - 1.0);
  state.counters["cost_a_pct"] = 100.0 * (with_a - 1.0);
  state.counters["cost_b_pct"] = 100.0 * (with_b - 1.0);
  state.SetLabel(std::string(backend_name(backend)) + " x1 exact");
}
BENCHMARK(BM_TileBoundsPaired)->ArgsProduct({{0, 1, 2, 3}, {256, 1024}, {1, 2}})
    ->ArgNames({"backend", "size", "substeps"})->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// One tile row's bounds outside the step (tile_row_alone.h): random displacements 17 rows deep in
// one column block, the pass, the flush or both, with the bounds table of SSE2 (the scalar and SSE
// backends), AVX2 or AVX-512. `s_per_node`: the time over the tile row's 16 x width nodes, to set
// against BM_Solver's time a node-step. Args: table (0 SSE2, 1 AVX2, 2 AVX-512), width, part
// (0 pass, 1 flush, 2 both).
void BM_TileRowAlone(benchmark::State& state) {
  const int table = static_cast<int>(state.range(0)), width = static_cast<int>(state.range(1));
  const struct {
    Backend needs;
    pond::bench::TileRowFn (*get)();  // called only after the CPU check, as the kernels' getters
  } tables[] = {{Backend::sse, &pond::bench::tile_row_sse2},
                {Backend::avx2, &pond::bench::tile_row_avx2},
                {Backend::avx512, &pond::bench::tile_row_avx512}};
  if (skipped_without(tables[table].needs, state)) return;
  const pond::bench::TileRowFn fn = tables[table].get();
  const int rows = 2 * POND_TILE_CELLS + 1;  // a second tile row, so row 16 ends no range
  // 64-byte aligned, as the solver's state and columns are (sim/aligned_buffer.h).
  AlignedBuffer<float> u[3];
  std::mt19937 rng(7);
  for (auto& a : u) {
    a = AlignedBuffer<float>(static_cast<std::size_t>(rows) * width);
    for (float& x : a) x = std::uniform_real_distribution<float>(-1, 1)(rng);
  }
  StepView view{};
  view.oux = u[0].data();
  view.ouy = u[1].data();
  view.ouz = u[2].data();
  view.rows = rows;
  view.cols = width;
  const TileGrid grid(rows, width);
  AlignedBuffer<float> columns(6 * kColumnsPitch);
  std::vector<TileBounds> tiles(grid.tiles());
  TileSink sink{tiles.data(), columns.data(), 0};
  const auto part = static_cast<pond::bench::TileRowPart>(state.range(2));
  for (auto _ : state) {
    fn(view, grid, part, sink);
    benchmark::DoNotOptimize(tiles.data());
    benchmark::ClobberMemory();
  }
  state.counters["s_per_node"] = benchmark::Counter(double(POND_TILE_CELLS) * width * double(state.iterations()),
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TileRowAlone)->ArgsProduct({{0, 1, 2}, {257, 1024}, {0, 1, 2}})
    ->ArgNames({"table", "width", "part"})->Unit(benchmark::kMicrosecond);

// The sweep behind docs/solver_speed.png (scripts/plot_solver_speed.sh): exact math, every backend,
// one thread and all threads, grid sizes from 32^2 to 2048^2.
void sweep_args(benchmark::internal::Benchmark* b) {
  const int all = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int size : {32, 64, 128, 256, 512, 1024, 2048})
    for (int backend : {0, 1, 2, 3})
      for (int threads : {1, all}) b->Args({backend, size, threads, 0});
}
BENCHMARK(BM_Solver)->Name("Sweep")->Apply(sweep_args)->ArgNames({"backend", "size", "threads", "fast"})
    ->Unit(benchmark::kMicrosecond)->UseRealTime()->MinTime(0.2);

// Copy bandwidth with all threads: the bound a memory-limited solver approaches. Reported as
// bytes/s read + written, and as the node-steps/s it would allow at 48 bytes per node.
void BM_CopyBandwidth(benchmark::State& state) {
  const std::size_t bytes = std::size_t{96} << 20;
  std::vector<char> src(bytes, 1), dst(bytes, 2);
  const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (auto _ : state) {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back([&, t] {
        const std::size_t part = bytes / threads;
        std::memcpy(dst.data() + part * t, src.data() + part * t, part);
      });
    for (auto& t : pool) t.join();
    benchmark::DoNotOptimize(dst.data());
  }
  const double moved = 2.0 * double(bytes) * double(state.iterations());
  state.counters["bytes_per_s"] = benchmark::Counter(moved, benchmark::Counter::kIsRate);
  state.counters["node_steps_per_s_bound"] = benchmark::Counter(moved / 48.0, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CopyBandwidth)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.5);

}  // namespace

BENCHMARK_MAIN();
