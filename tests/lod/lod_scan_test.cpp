// The exact triangle scan (triangle_scan.h) against a node-by-node check in double, and the
// builder's meshes the same with the AVX2 node budgets hidden (POND_CPU_FEATURES_MASK) as with them.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/cpu_features_mask.h"
#include "lod/lod_builder.h"
#include "lod/range_proof.h"
#include "lod/rippled_states.h"
#include "lod/surface_blocks.h"
#include "lod/tile_ranges.h"
#include "lod/triangle_scan.h"

namespace pond::lod_test {
namespace {

// Every triangle of the hierarchy inside the grid, at most `widest` cells across, with the parts
// the builder scans against it: itself, its two children and its four grandchildren.
struct Scan {
  lod::Tri t, region;
};
void collect(const lod::GridHierarchy& g, const lod::Tri& t, int widest, std::vector<Scan>& out) {
  lod::Point m;
  if (!lod::midpoint(t, m)) return;
  const lod::CellBox box = lod::box_of(t);
  if (g.within_grid(t) && box.x1 - box.x0 <= widest && box.y1 - box.y0 <= widest) {
    out.push_back({t, t});
    for (const lod::Tri& half : {lod::child_left(t, m), lod::child_right(t, m)}) {
      out.push_back({t, half});
      lod::Point c;
      if (!lod::midpoint(half, c)) continue;
      out.push_back({t, lod::child_left(half, c)});
      out.push_back({t, lod::child_right(half, c)});
    }
  }
  collect(g, lod::child_left(t, m), widest, out);
  collect(g, lod::child_right(t, m), widest, out);
}

// The verdict node by node in double, from integer barycentric weights; `near` is set when a node
// lies so close to its budget (1e-9 relative) that two correct computations may differ.
bool within_in_double(const lod::SurfaceBlock& b, const lod::Tri& t, const lod::Tri& region, bool& near) {
  const lod::GridHierarchy& g = *b.grid;
  const lod::Point c[3] = {t.apex, t.left, t.right};
  const long long det = static_cast<long long>(c[1].x - c[0].x) * (c[2].y - c[0].y) -
                        static_cast<long long>(c[1].y - c[0].y) * (c[2].x - c[0].x);
  const lod::CellBox box = lod::box_of(region);
  const lod::Point r[3] = {region.apex, region.left, region.right};
  bool within = true;
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x) {
      // The weight of the corner opposite edge (e, f), times det.
      const auto weight = [&](lod::Point e, lod::Point f) {
        return static_cast<long long>(e.x - x) * (f.y - y) - static_cast<long long>(e.y - y) * (f.x - x);
      };
      bool in_region = true;
      for (int k = 0; k < 3; ++k) {
        const lod::Point a = r[k], e = r[(k + 1) % 3], f = r[(k + 2) % 3];
        const long long inner = static_cast<long long>(e.x - x) * (f.y - y) - static_cast<long long>(e.y - y) * (f.x - x);
        const long long whole = static_cast<long long>(e.x - a.x) * (f.y - a.y) - static_cast<long long>(e.y - a.y) * (f.x - a.x);
        in_region = in_region && (whole > 0 ? inner >= 0 : inner <= 0);
      }
      if (!in_region) continue;
      double miss2 = 0;
      const std::uint32_t n = g.id({x, y});
      for (const std::vector<float>* v : {&b.x, &b.y, &b.z}) {
        double at = 0;
        for (int k = 0; k < 3; ++k)
          at += double(weight(c[(k + 1) % 3], c[(k + 2) % 3])) / double(det) * (*v)[g.id(c[k])];
        const double d = (*v)[n] - at;
        miss2 += d * d;
      }
      const double budget = b.budget[n];
      if (std::isfinite(budget) && budget > 0 && std::abs(std::sqrt(miss2) - budget) <= 1e-9 * budget) near = true;
      within = within && miss2 <= budget * budget;
    }
  return within;
}

// The whole grid of `p` read as one block from `cam` at `tau`, with its tile ranges and box budgets.
struct WholeGrid {
  WholeGrid(const lod::NodePositions& p, const lod::Camera& cam, double tau)
      : ranges(lod::tile_ranges(p)), largest(ranges.largest()), blocks(p.rows, p.cols),
        terms(lod::budget_terms(cam, tau, largest)), box_budget(terms) {
    blocks.begin(p, terms, largest, ranges, box_budget);
  }
  const lod::SurfaceBlock& block() { return blocks.whole(); }
  // Every triangle of at most a block whose box `keep` takes: where the tile ranges prove it, its
  // nodes must too. Returns how many the ranges proved.
  template <class Keep>
  int ranges_prove_only_what_nodes_do(Keep keep) {
    const lod::SurfaceBlock& w = block();
    std::vector<Scan> scans;
    for (const lod::Tri& root : w.grid->roots()) collect(*w.grid, root, lod::kBlockCells, scans);
    int proved = 0;
    for (const Scan& s : scans) {
      const lod::CellBox box = lod::box_of(s.t);
      const lod::Point corners[3] = {s.t.apex, s.t.left, s.t.right};
      if (!(s.region.apex == s.t.apex && s.region.left == s.t.left && s.region.right == s.t.right) || !keep(box) ||
          !lod::RangeProof(ranges, box_budget).proves(box.x0, box.x1, box.y0, box.y1, corners))
        continue;
      ++proved;
      EXPECT_TRUE(lod::within_budget(*w.grid, w.positions(), w.scan_budgets(), largest, s.t, nullptr))
          << "apex " << s.t.apex.x << "," << s.t.apex.y << " left " << s.t.left.x << "," << s.t.left.y;
    }
    return proved;
  }
  lod::TileRanges ranges;
  float largest;
  lod::SurfaceBlocks blocks;
  lod::BudgetTerms terms;
  lod::BoxBudget box_budget;
};

// Rain and calm water with a few rings, from above, grazing and inside, at three tolerances: every
// scan of a part the builder may scan, against the check in double.
TEST(TriangleScan, VerdictsAreTheExactOnes) {
  for (const auto& [what, state] : {std::pair<std::string, std::vector<float>>{"rain", simulated_pond(65, 65, 60, 6, 10, 3)},
                                    {"rings", simulated_pond(65, 65, 4, 1, 30, 5)}}) {
    const auto p = lod::interleaved_positions(state.data(), 65, 65);
    const lod::Camera views[] = {{{32, 40, -20}, {32, 0, 32}, 60, 1280, 720},
                                 {{32, 1.5, -10}, {32, 0.3, 40}, 50, 1280, 720},
                                 {{30, 2, 30}, {60, 0, 40}, 90, 640, 480}};
    for (const lod::Camera& cam : views)
      for (double tau : {0.3, 1.0, 3.0}) {
        WholeGrid whole(p, cam, tau);
        const lod::SurfaceBlock& w = whole.block();
        const float largest = whole.largest;
        std::vector<Scan> scans;
        for (const lod::Tri& root : w.grid->roots()) collect(*w.grid, root, 32, scans);
        int fine = 0, decided = 0;
        for (const Scan& s : scans) {
          bool near = false;
          const bool expected = within_in_double(w, s.t, s.region, near);
          // The SSE2 copy, and the AVX2 one where it runs: the same verdict, near or not.
          lod::ScanBudgets budgets = w.scan_budgets();
          budgets.wide = false;
          const bool within = lod::within_budget(*w.grid, w.positions(), budgets, largest, s.t, s.region, nullptr);
          if (lod::wide_budgets_available()) {
            budgets.wide = true;
            ASSERT_EQ(lod::within_budget(*w.grid, w.positions(), budgets, largest, s.t, s.region, nullptr), within)
                << what << " tau " << tau << " apex " << s.t.apex.x << "," << s.t.apex.y;
          }
          if (!near) {
            ASSERT_EQ(within, expected) << what << " tau " << tau << " apex " << s.t.apex.x << "," << s.t.apex.y
                                        << " region apex " << s.region.apex.x << "," << s.region.apex.y;
            ++decided;
          }
          fine += within;
        }
        // Both verdicts occur, and nearly every scan is decided by the check.
        EXPECT_GT(fine, 0) << what << " tau " << tau;
        EXPECT_LT(fine, static_cast<int>(scans.size())) << what << " tau " << tau;
        EXPECT_GT(decided, static_cast<int>(scans.size()) * 99 / 100);
      }
  }
}

// The tile ranges never prove a block-sized triangle its nodes do not (camera_budget.h: the box
// budgets are at most the nodes' own), so the builder judges a triangle whose block is made on its
// nodes alone. Calm water (where the ranges prove the most) and rain, from above, grazing, and from
// inside the pond with its nearest nodes' budgets near 0.
TEST(TriangleScan, RangesProveNoTriangleItsNodesDoNot) {
  int proved = 0;
  for (const std::vector<float>& state : {simulated_pond(65, 65, 2, 1, 40, 5), simulated_pond(65, 65, 60, 6, 10, 3)})
    for (const lod::Camera& cam : {lod::Camera{{32, 40, -20}, {32, 0, 32}, 60, 1280, 720},
                                   lod::Camera{{32, 1.5, -10}, {32, 0.3, 40}, 50, 1280, 720},
                                   lod::Camera{{30, 0.05, 30}, {60, 0, 40}, 90, 640, 480}})
      for (double tau : {0.3, 3.0})
        proved += WholeGrid(lod::interleaved_positions(state.data(), 65, 65), cam, tau)
                      .ranges_prove_only_what_nodes_do([](const lod::CellBox&) { return true; });
  EXPECT_GT(proved, 1000);
}

// The same where it is tight: calm water with one node raised by about its own budget, seen along
// +z (no x in the view direction), so that the node is the nearest point of its cells' boxes and
// the ranges bound its miss exactly. Raised a millionth of its budget at a time across it, no
// triangle over it is proved by the ranges and refused by its nodes.
TEST(TriangleScan, RangesProveNoTriangleItsNodesDoNotAtTheEdge) {
  constexpr int kSide = 65, kRow = 32, kCol = 22;
  const lod::Camera cam{{32, 6, -20}, {32, 0, 40}, 60, 1280, 720};
  const std::size_t n = static_cast<std::size_t>(kRow * kSide + kCol);
  std::vector<float> state = flat_pond(kSide, kSide);
  const auto raised_by = [&](float height) {
    state[6 * n + 1] = height;
    return WholeGrid(lod::interleaved_positions(state.data(), kSide, kSide), cam, 1.0);
  };
  const float budget = raised_by(raised_by(0.05f).block().budget[n]).block().budget[n];  // its budget raised so far
  int proved = 0;
  for (int k = -40; k <= 40; ++k)
    proved += raised_by(budget * static_cast<float>(1 + k * 1e-6)).ranges_prove_only_what_nodes_do([](const lod::CellBox& b) {
      return b.x0 <= kCol && kCol <= b.x1 && b.y0 <= kRow && kRow <= b.y1;
    });
  EXPECT_GT(proved, 40);
}

// The builder, frame after frame (blocks first, then the whole grid), draws the same triangles with
// the AVX2 copies of the node budgets and the scan as with the SSE2 ones.
TEST(LodBuilder, SameMeshWithTheAvx2CopiesHidden) {
  if (!lod::wide_budgets_available()) GTEST_SKIP() << "no AVX2 copy in this build, or no AVX2 on this CPU";
  const std::vector<float> state = simulated_pond(129, 129, 150, 10, 10, 7);
  const auto p = lod::interleaved_positions(state.data(), 129, 129);
  const lod::Camera views[] = {{{64, 30, -15}, {64, 0, 60}, 60, 1280, 720},
                               {{64, 1.2, -5}, {64, 0.2, 80}, 50, 1280, 720},
                               {{60, 3, 60}, {100, 0, 70}, 90, 1280, 720}};
  int whole_frames = 0;
  for (const lod::Camera& cam : views) {
    lod::LodBuilder wide(129, 129), narrow(129, 129);
    std::vector<std::uint32_t> a(wide.max_indices()), b(narrow.max_indices());
    for (int frame = 0; frame < 2; ++frame) {
      const std::size_t na = wide.build(p, cam, 1.0, a);
      std::size_t nb = 0;
      {
        const test::CpuFeaturesMask mask("avx2");
        nb = narrow.build(p, cam, 1.0, b);
      }
      ASSERT_EQ(na, nb) << "frame " << frame;
      EXPECT_TRUE(std::equal(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(na), b.begin())) << "frame " << frame;
      EXPECT_GT(wide.stats().scanned, 0) << "frame " << frame;
      whole_frames += wide.stats().whole;
    }
  }
  EXPECT_GT(whole_frames, 0);  // the whole grid's scans by parts too
}

// The scans' tables are kept per pitch of the arrays scanned (a few at a time): scans of grids of
// five widths, interleaved so that each width's tables are made again and again, give the
// verdicts of the check in double, in both copies.
// The sure-within thresholds: the AVX2 copy writes the baseline's bits, each the formula's in
// scalar float, for every count (the last group runs into the padding) and budgets from 0 to +inf.
TEST(TriangleScan, ThresholdsAreTheSameWideOrNot) {
  const float largest = 300;
  const float slack = 64 * largest * std::numeric_limits<float>::epsilon();
  std::vector<float> budget;
  for (int k = 0; k < 40; ++k)
    budget.push_back(k % 7 == 0 ? 0.0f : k % 11 == 0 ? INFINITY : slack * static_cast<float>(k % 5) * 0.5f + 1e-3f * static_cast<float>(k));
  for (std::size_t n = 1; n <= 32; ++n) {
    std::vector<float> narrow(n + lod::kScanOverread, -1), wide(n + lod::kScanOverread, -1);
    lod::scan_thresholds(budget.data(), n, largest, narrow.data(), false);
    if (!lod::wide_budgets_available()) continue;
    lod::scan_thresholds(budget.data(), n, largest, wide.data(), true);
    for (std::size_t k = 0; k < n; ++k) {
      const float low = std::max(budget[k] - slack, 0.0f);
      const float expected = low * low * (1 - 1e-6f);
      ASSERT_EQ(std::bit_cast<std::uint32_t>(narrow[k]), std::bit_cast<std::uint32_t>(expected)) << n << " " << k;
      ASSERT_EQ(std::bit_cast<std::uint32_t>(wide[k]), std::bit_cast<std::uint32_t>(expected)) << n << " " << k;
    }
  }
}

TEST(TriangleScan, TablesOfManyPitchesInTurn) {
  struct Grid {
    explicit Grid(int side) : state(simulated_pond(side, side, 20, 4, 10, 3)), blocks(side, side) {}
    std::vector<float> state;
    lod::SurfaceBlocks blocks;
    float largest = 0;
    std::vector<Scan> scans;
  };
  std::vector<std::unique_ptr<Grid>> grids;
  for (int side : {17, 24, 33, 40, 65}) {
    Grid& g = *grids.emplace_back(std::make_unique<Grid>(side));
    const auto p = lod::interleaved_positions(g.state.data(), side, side);
    const lod::TileRanges ranges = lod::tile_ranges(p);
    g.largest = ranges.largest();
    const double s = side / 2.0;
    const lod::BudgetTerms terms = lod::budget_terms({{s, side * 0.6, -s}, {s, 0, s}, 60, 1280, 720}, 0.5, g.largest);
    g.blocks.begin(p, terms, g.largest, ranges, lod::BoxBudget(terms));
    for (const lod::Tri& root : g.blocks.whole().grid->roots()) collect(*g.blocks.whole().grid, root, 16, g.scans);
  }
  int fine = 0, total = 0;
  for (std::size_t k = 0;; ++k) {
    bool any = false;
    for (const auto& grid : grids) {
      Grid& g = *grid;
      if (k >= g.scans.size()) continue;
      any = true;
      const lod::SurfaceBlock& w = g.blocks.whole();
      const Scan& s = g.scans[k];
      lod::ScanBudgets budgets = w.scan_budgets();
      budgets.wide = false;
      const bool within = lod::within_budget(*w.grid, w.positions(), budgets, g.largest, s.t, s.region, nullptr);
      if (lod::wide_budgets_available()) {
        budgets.wide = true;
        ASSERT_EQ(lod::within_budget(*w.grid, w.positions(), budgets, g.largest, s.t, s.region, nullptr), within)
            << w.grid->cols() << " wide, scan " << k;
      }
      bool near = false;
      const bool expected = within_in_double(w, s.t, s.region, near);
      if (!near) {
        ASSERT_EQ(within, expected) << w.grid->cols() << " wide, scan " << k;
      }
      fine += within, ++total;
    }
    if (!any) break;
  }
  EXPECT_GT(fine, 0);
  EXPECT_LT(fine, total);
}

}  // namespace
}  // namespace pond::lod_test
