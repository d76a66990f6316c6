// The LOD builder's speed and value. Scenes: a pond seen from 35 units up at 1280x720, looking
// across it. "rain": one drop per 160 nodes over 20 steps (vertical velocity 0.03-0.1 each),
// waves everywhere up to about 1 unit high; "storm": the same drops ten times stronger (waves up to
// 4 units); "splashes": six strong splashes spreading for 60 steps. The rain runs at 50² to 4097².
#include <benchmark/benchmark.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "lod/camera_budget.h"
#include "lod/error_bounds.h"
#include "lod/lod_builder.h"
#include "lod/position_copy.h"
#include "lod/mesh_checker.h"
#include "lod/rippled_states.h"
#include "lod/triangle_scan.h"

namespace {

using pond::lod_test::CheckCamera;

struct Pond {
  int side;
  std::vector<float> state;
  pond::lod::NodePositions positions() const { return pond::lod::interleaved_positions(state.data(), side, side); }
  // The tile ranges a running pond gets from its solver's step (timed apart: BM_TileRangesFromState).
  const pond::lod::TileRanges& ranges() const {
    if (!ranges_) ranges_ = pond::lod::tile_ranges(positions());
    return *ranges_;
  }
  mutable std::optional<pond::lod::TileRanges> ranges_{};
  // The same nodes as a running CPU solver hands them to the renderer (water_source.cpp): three
  // arrays of displacements from the rest grid (spacing 1), in grid units. col + (x - col) is x
  // again exactly, so the builder sees the same world positions.
  pond::lod::NodePositions solver_positions() const {
    if (ux_.empty()) {
      const std::size_t n = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
      ux_.resize(n), uy_.resize(n), uz_.resize(n);
      for (std::size_t k = 0; k < n; ++k) {
        ux_[k] = state[6 * k] - static_cast<float>(k % static_cast<std::size_t>(side));
        uy_[k] = state[6 * k + 1];
        uz_[k] = state[6 * k + 2] - static_cast<float>(k / static_cast<std::size_t>(side));
      }
    }
    return pond::lod::grid_displacements(ux_.data(), uy_.data(), uz_.data(), side, side, 1.0f);
  }
  mutable std::vector<float> ux_{}, uy_{}, uz_{};
};

const Pond& drops_everywhere(int side, double amplitude) {
  static std::map<std::pair<int, double>, Pond> cache;
  auto it = cache.find({side, amplitude});
  if (it == cache.end()) {
    const int drops = side * side / 160;
    it = cache.emplace(std::pair{side, amplitude},
                       Pond{side, pond::lod_test::simulated_pond(side, side, drops, std::max(1, drops / 20),
                                                                 15, 1, amplitude)}).first;
  }
  return it->second;
}
const Pond& rain(int side) { return drops_everywhere(side, 0.1); }
const Pond& storm(int side) { return drops_everywhere(side, 1.0); }

const Pond& splashes(int side) {
  static std::map<int, Pond> cache;
  auto it = cache.find(side);
  if (it == cache.end())
    it = cache.emplace(side, Pond{side, pond::lod_test::simulated_pond(side, side, 6, 1, 60, 2)}).first;
  return it->second;
}

// From 35 units up over the near shore, looking across the pond (scaled with its size).
CheckCamera view(int side) {
  const double s = (side - 1) / 256.0;
  return {{128 * s, 35 * s, -20 * s}, {128 * s, 0, 110 * s}, 60, 1280, 720};
}

pond::lod::Camera lod_camera(const CheckCamera& c) {
  return {c.eye, c.target, c.fovy_degrees, c.width, c.height};
}

std::vector<std::uint32_t> build(const Pond& p, const CheckCamera& c, double tau,
                                 pond::lod::BuildStats* stats = nullptr) {
  pond::lod::LodBuilder b(p.side, p.side);
  std::vector<std::uint32_t> out(b.max_indices());
  out.resize(b.build(p.positions(), p.ranges(), lod_camera(c), tau, out));
  if (stats) *stats = b.stats();
  return out;
}

void report_counts(benchmark::State& st, std::size_t tris, int side) {
  st.counters["triangles"] = static_cast<double>(tris);
  st.counters["pct_full"] = 100.0 * static_cast<double>(tris) / (2.0 * (side - 1) * (side - 1));
}

// The whole-grid block's three passes over every node, each timed alone (257² rain, the view of
// BM_BuildRain): range(1) 0 the copy to world positions, 1 the budgets, 2 the nested bounds.
void BM_WholeGridPass(benchmark::State& st) {
  const int side = static_cast<int>(st.range(0));
  const Pond& p = rain(side);
  const std::size_t n = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
  std::vector<float> x(n + 3), y(n + 3), z(n + 3), budget(n + 3);
  const float largest = pond::lod::copy_finite_window(p.positions(), 0, 0, side, side, x.data(), y.data(), z.data());
  const pond::lod::NodePositions own = pond::lod::soa_positions(x.data(), y.data(), z.data(), side, side);
  const pond::lod::BudgetTerms terms = pond::lod::budget_terms(lod_camera(view(side)), 1.0, largest);
  pond::lod::node_budgets(own, terms, budget.data());
  const pond::lod::GridHierarchy grid(side, side);
  std::vector<pond::lod::NestedBound> bounds(n, pond::lod::kNothingProved);
  for (auto _ : st) {
    switch (st.range(1)) {
      case 0: pond::lod::copy_finite_block(p.positions(), 0, 0, side, side, x.data(), y.data(), z.data()); break;
      case 1: pond::lod::node_budgets(own, terms, budget.data()); break;
      default: pond::lod::nested_bounds(grid, own, largest, budget.data(), bounds.data()); break;
    }
    benchmark::ClobberMemory();
  }
  st.counters["ns_per_node"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate |
                                                                            benchmark::Counter::kInvert);
}
BENCHMARK(BM_WholeGridPass)->ArgsProduct({{257, 1025}, {0, 1, 2}})->Unit(benchmark::kMicrosecond);

// The block copy alone (surface_blocks.h: 17x17 nodes of a 1025² state): range(0) 0 the 466
// blocks of a 1025² rain frame's count at random places, 1 one block 466 times (always in cache).
void BM_BlockCopy(benchmark::State& st) {
  const Pond& p = rain(1025);
  std::vector<std::pair<int, int>> at;
  std::mt19937 rng(1);
  constexpr int kCells = pond::lod::kBlockCells, kNodes = kCells + 1;
  std::uniform_int_distribution<int> block(0, (1025 - 2) / kCells);
  for (int k = 0; k < 466; ++k) at.emplace_back(st.range(0) ? 0 : block(rng), st.range(0) ? 0 : block(rng));
  std::vector<float> x(kNodes * kNodes + pond::lod::kScanOverread), y(x.size()), z(x.size());
  for (auto _ : st)
    for (auto [bx, by] : at) {
      pond::lod::copy_finite_block(p.positions(), by * kCells, bx * kCells, kNodes, kNodes, x.data(), y.data(), z.data());
      benchmark::ClobberMemory();
    }
}
BENCHMARK(BM_BlockCopy)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// Build time per frame (the surface is the same each iteration; the builder redoes everything),
// from `positions` of the rain pond.
void time_builds(benchmark::State& st, pond::lod::LodBuilder& b, const pond::lod::NodePositions& positions,
                        const Pond& p) {
  const int side = p.side;
  std::vector<std::uint32_t> out(b.max_indices());
  std::size_t n = 0;
  for (auto _ : st) {
    n = b.build(positions, p.ranges(), lod_camera(view(side)), 1.0, out);
    benchmark::DoNotOptimize(out.data());
  }
  report_counts(st, n / 3, side);
  st.counters["blocks"] = static_cast<double>(b.stats().blocks);
}

void BM_BuildRain(benchmark::State& st) {
  const Pond& p = rain(static_cast<int>(st.range(0)));
  pond::lod::LodBuilder b(p.side, p.side);
  time_builds(st, b, p.positions(), p);
  st.counters["tested_tris"] = static_cast<double>(b.stats().tested);
  st.counters["ranged_tris"] = static_cast<double>(b.stats().ranged);
  st.counters["scanned_tris"] = static_cast<double>(b.stats().scanned);
  st.counters["proved_tris"] = static_cast<double>(b.stats().proved);
  st.counters["scan_nodes"] = static_cast<double>(b.stats().scanned_nodes);
}
BENCHMARK(BM_BuildRain)->Arg(50)->Arg(257)->Arg(1025)->Arg(2049)->Arg(4097)->Unit(benchmark::kMillisecond);

// BM_BuildRain's frames in the layout the live frame reads with a CPU solver (Pond::solver_positions):
// the same meshes, with the copies reading three arrays of displacements instead of interleaved records.
void BM_BuildRainSolverLayout(benchmark::State& st) {
  const Pond& p = rain(static_cast<int>(st.range(0)));
  pond::lod::LodBuilder b(p.side, p.side);
  time_builds(st, b, p.solver_positions(), p);
}
BENCHMARK(BM_BuildRainSolverLayout)->Arg(257)->Arg(1025)->Arg(2049)->Arg(4097)->Unit(benchmark::kMillisecond);

// Frame-to-frame coherence, measured for a design not built yet: how many of one frame's leaves in
// view would pass again one step later, proved from what they missed by then plus twice the most
// any node of their tiles moved (a tile bound a solver could emit), without reading a node.
// Counters: leaves in view; re-proved with each node's own miss and budget ("per_node"), with the
// leaf's largest miss against its least budget ("per_leaf", what a stored slack would give), and
// that with the most any node of the pond moved ("per_leaf_global", a bound a kernel keeps in a
// register) in place of its tiles'.
void BM_LeafCoherence(benchmark::State& st) {
  const int side = static_cast<int>(st.range(0)), drops = side * side / 160;
  const auto before = pond::lod_test::simulated_pond(side, side, drops, std::max(1, drops / 20), 15, 1, 0.1);
  const auto after = pond::lod_test::simulated_pond(side, side, drops, std::max(1, drops / 20), 16, 1, 0.1);
  const auto pa = pond::lod::interleaved_positions(before.data(), side, side);
  const auto pb = pond::lod::interleaved_positions(after.data(), side, side);
  const pond::lod::TileRanges ranges = pond::lod::tile_ranges(pa);
  const pond::lod::Camera camera = lod_camera(view(side));
  const std::size_t n = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
  const auto at = [&](const std::vector<float>& s, std::size_t node, int c) { return double(s[node * 6 + c]); };
  std::vector<std::uint32_t> leaves;
  std::vector<float> x(n + 3), y(n + 3), z(n + 3), budget(n + 3);
  std::vector<double> tile_move;
  for (auto _ : st) {
    pond::lod::LodBuilder b(side, side);
    leaves.resize(b.max_indices());
    leaves.resize(b.build(pa, ranges, camera, 1.0, leaves));
    const float largest = pond::lod::copy_finite_window(pb, 0, 0, side, side, x.data(), y.data(), z.data());
    pond::lod::node_budgets(pond::lod::soa_positions(x.data(), y.data(), z.data(), side, side),
                            pond::lod::budget_terms(camera, 1.0, largest), budget.data());
    // The most a node of each tile moved (tile (a, b): nodes 16 a .. 16 a + 16 by 16 b .. 16 b + 16).
    tile_move.assign(static_cast<std::size_t>(ranges.tiles_x()) * ranges.tiles_y(), 0.0);
    for (int tb = 0; tb < ranges.tiles_y(); ++tb)
      for (int ta = 0; ta < ranges.tiles_x(); ++ta)
        for (int r = 16 * tb; r <= std::min(16 * tb + 16, side - 1); ++r)
          for (int c = 16 * ta; c <= std::min(16 * ta + 16, side - 1); ++c) {
            const std::size_t k = static_cast<std::size_t>(r) * side + c;
            double d2 = 0;
            for (int i = 0; i < 3; ++i) d2 += std::pow(at(after, k, i) - at(before, k, i), 2);
            double& m = tile_move[static_cast<std::size_t>(tb) * ranges.tiles_x() + ta];
            m = std::max(m, std::sqrt(d2));
          }
    const double pond_move = *std::max_element(tile_move.begin(), tile_move.end());
    std::size_t in_view = 0, per_node = 0, per_leaf = 0, per_leaf_global = 0;
    // The blocks (surface_blocks.h, by a leaf's first node) holding a leaf either bound fails: what a
    // frame would still make to test those leaves again.
    const std::size_t blocks_x = static_cast<std::size_t>(side) / pond::lod::kBlockCells + 1;
    std::vector<char> failing_tile(blocks_x * blocks_x), failing_pond(blocks_x * blocks_x);
    for (std::size_t t = 0; t + 2 < leaves.size(); t += 3) {
      const std::uint32_t id[3] = {leaves[t], leaves[t + 1], leaves[t + 2]};
      int px[3], py[3];
      for (int k = 0; k < 3; ++k) px[k] = static_cast<int>(id[k]) % side, py[k] = static_cast<int>(id[k]) / side;
      const long long det = (long long)(px[1] - px[0]) * (py[2] - py[0]) - (long long)(py[1] - py[0]) * (px[2] - px[0]);
      if (det == 0) continue;
      const int x0 = std::min({px[0], px[1], px[2]}), x1 = std::max({px[0], px[1], px[2]});
      const int y0 = std::min({py[0], py[1], py[2]}), y1 = std::max({py[0], py[1], py[2]});
      // The most a node of the tiles holding the leaf's box moved.
      const pond::lod::TileRect r = ranges.tiles_of(x0, x1, y0, y1);
      double move = 0;
      for (int tb = r.b0; tb <= r.b1; ++tb)
        for (int ta = r.a0; ta <= r.a1; ++ta) move = std::max(move, tile_move[static_cast<std::size_t>(tb) * ranges.tiles_x() + ta]);
      // Over the leaf's nodes in view (barycentric weights times det, exact integers): the largest
      // miss less the node's budget, the largest miss, the least budget.
      double over = -HUGE_VAL, largest_miss = 0, least_budget = HUGE_VAL;
      for (int yy = y0; yy <= y1; ++yy)
        for (int xx = x0; xx <= x1; ++xx) {
          const long long wb = (long long)(xx - px[0]) * (py[2] - py[0]) - (long long)(yy - py[0]) * (px[2] - px[0]);
          const long long wc = (long long)(px[1] - px[0]) * (yy - py[0]) - (long long)(py[1] - py[0]) * (xx - px[0]);
          const long long wa = det - wb - wc;
          const std::size_t k = static_cast<std::size_t>(yy) * side + xx;
          const bool inside = det > 0 ? (wa >= 0 && wb >= 0 && wc >= 0) : (wa <= 0 && wb <= 0 && wc <= 0);
          if (!inside || !std::isfinite(budget[k])) continue;
          double e2 = 0;
          for (int c = 0; c < 3; ++c)
            e2 += std::pow(at(before, k, c) - (double(wa) * at(before, id[0], c) + double(wb) * at(before, id[1], c) +
                                               double(wc) * at(before, id[2], c)) / double(det), 2);
          over = std::max(over, std::sqrt(e2) - budget[k]);
          largest_miss = std::max(largest_miss, std::sqrt(e2)), least_budget = std::min(least_budget, double(budget[k]));
        }
      if (least_budget == HUGE_VAL) continue;  // wholly out of view
      ++in_view, per_node += over + 2 * move <= 0, per_leaf += largest_miss + 2 * move <= least_budget;
      per_leaf_global += largest_miss + 2 * pond_move <= least_budget;
      const std::size_t block = static_cast<std::size_t>(y0 / pond::lod::kBlockCells) * blocks_x +
                                static_cast<std::size_t>(x0 / pond::lod::kBlockCells);
      if (!(largest_miss + 2 * move <= least_budget)) failing_tile[block] = 1;
      if (!(largest_miss + 2 * pond_move <= least_budget)) failing_pond[block] = 1;
    }
    st.counters["in_view"] = static_cast<double>(in_view);
    st.counters["per_node"] = static_cast<double>(per_node);
    st.counters["per_leaf"] = static_cast<double>(per_leaf);
    st.counters["per_leaf_global"] = static_cast<double>(per_leaf_global);
    st.counters["blocks_failing_tile"] = static_cast<double>(std::count(failing_tile.begin(), failing_tile.end(), 1));
    st.counters["blocks_failing_pond"] = static_cast<double>(std::count(failing_pond.begin(), failing_pond.end(), 1));
  }
}
BENCHMARK(BM_LeafCoherence)->Arg(257)->Arg(1025)->Iterations(1)->Unit(benchmark::kMillisecond);

// What `pond lod` spends before building from a file's state: its tile ranges, node by node.
void BM_TileRangesFromState(benchmark::State& st) {
  const Pond& p = rain(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(pond::lod::tile_ranges(p.positions()).largest());
}
BENCHMARK(BM_TileRangesFromState)->Arg(257)->Arg(1025)->Arg(4097)->Unit(benchmark::kMillisecond);

void BM_BuildSplashes(benchmark::State& st) {
  const int side = static_cast<int>(st.range(0));
  const Pond& p = splashes(side);
  pond::lod::LodBuilder b(side, side);
  std::vector<std::uint32_t> out(b.max_indices());
  std::size_t n = 0;
  for (auto _ : st) {
    n = b.build(p.positions(), p.ranges(), lod_camera(view(side)), 1.0, out);
    benchmark::DoNotOptimize(out.data());
  }
  report_counts(st, n / 3, side);
}
BENCHMARK(BM_BuildSplashes)->Arg(257)->Unit(benchmark::kMillisecond);

void BM_BuildStorm(benchmark::State& st) {
  const int side = static_cast<int>(st.range(0));
  const Pond& p = storm(side);
  pond::lod::LodBuilder b(side, side);
  std::vector<std::uint32_t> out(b.max_indices());
  std::size_t n = 0;
  for (auto _ : st) {
    n = b.build(p.positions(), p.ranges(), lod_camera(view(side)), 1.0, out);
    benchmark::DoNotOptimize(out.data());
  }
  report_counts(st, n / 3, side);
}
BENCHMARK(BM_BuildStorm)->Arg(257)->Unit(benchmark::kMillisecond);

// Triangle counts against tolerance (x10: 5 = 0.5 px), rain-covered and few-splashes 257^2.
void BM_CountsRain(benchmark::State& st) {
  const double tau = static_cast<double>(st.range(0)) / 10;
  std::size_t n = 0;
  for (auto _ : st) n = build(rain(257), view(257), tau).size() / 3;
  report_counts(st, n, 257);
}
BENCHMARK(BM_CountsRain)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_CountsSplashes(benchmark::State& st) {
  const double tau = static_cast<double>(st.range(0)) / 10;
  std::size_t n = 0;
  for (auto _ : st) n = build(splashes(257), view(257), tau).size() / 3;
  report_counts(st, n, 257);
}
BENCHMARK(BM_CountsSplashes)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_CountsStorm(benchmark::State& st) {
  const double tau = static_cast<double>(st.range(0)) / 10;
  std::size_t n = 0;
  for (auto _ : st) n = build(storm(257), view(257), tau).size() / 3;
  report_counts(st, n, 257);
}
BENCHMARK(BM_CountsStorm)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Iterations(1)->Unit(benchmark::kMillisecond);

// Vertex-cache efficiency (ACMR, FIFO of 16) of our Sierpinski order against
// meshopt_optimizeVertexCache on the very same triangles.
void BM_Acmr(benchmark::State& st) {
  const std::vector<std::uint32_t> ours = build(rain(257), view(257), 1.0);
  std::vector<std::uint32_t> tuned(ours.size());
  const std::size_t nodes = 257 * 257;
  for (auto _ : st) meshopt_optimizeVertexCache(tuned.data(), ours.data(), ours.size(), nodes);
  st.counters["acmr_ours"] = meshopt_analyzeVertexCache(ours.data(), ours.size(), nodes, 16, 0, 0).acmr;
  st.counters["acmr_meshopt"] = meshopt_analyzeVertexCache(tuned.data(), tuned.size(), nodes, 16, 0, 0).acmr;
  report_counts(st, ours.size() / 3, 257);
}
BENCHMARK(BM_Acmr)->Unit(benchmark::kMillisecond);

// The maximum screen error of meshopt_simplify (view-independent, border locked) brought to our
// triangle count, measured by the same independent checker as ours. Timed: the simplification.
void BM_VersusMeshoptSimplify(benchmark::State& st) {
  const double tau = static_cast<double>(st.range(0)) / 10;
  const Pond& p = rain(257);
  const CheckCamera cam = view(257);
  const std::vector<std::uint32_t> ours = build(p, cam, tau);
  const int side = p.side;
  std::vector<std::uint32_t> full;
  for (int i = 0; i + 1 < side; ++i)
    for (int j = 0; j + 1 < side; ++j) {
      const std::uint32_t a = static_cast<std::uint32_t>(i * side + j), b = a + 1,
                          c = a + static_cast<std::uint32_t>(side), d = c + 1;
      full.insert(full.end(), {a, c, d, a, d, b});  // rest normal +y
    }
  std::vector<std::uint32_t> simplified(full.size());
  std::size_t n = 0;
  for (auto _ : st)
    n = meshopt_simplify(simplified.data(), full.data(), full.size(), p.state.data(),
                         static_cast<std::size_t>(side) * side, 6 * sizeof(float), ours.size(), 1.0f,
                         meshopt_SimplifyLockBorder, nullptr);
  simplified.resize(n);
  const auto e_ours = pond::lod_test::screen_errors(ours, side, side, p.state, cam);
  const auto e_meshopt = pond::lod_test::screen_errors(simplified, side, side, p.state, cam);
  st.counters["tris_ours"] = static_cast<double>(ours.size() / 3);
  st.counters["tris_meshopt"] = static_cast<double>(n / 3);
  st.counters["maxerr_px_ours"] = e_ours.max_error_px;
  st.counters["maxerr_px_meshopt"] = e_meshopt.max_error_px;
  st.counters["uncovered_meshopt"] = static_cast<double>(e_meshopt.uncovered);
}
BENCHMARK(BM_VersusMeshoptSimplify)->Arg(10)->Arg(40)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
