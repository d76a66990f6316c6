// The parts of the top-down LOD builder: the tile ranges (every node inside its tiles' ranges, from a
// file's positions and from the solver's tile bounds), the whole grid's nested bounds (node by node;
// blocks have none), and the builder on the solver's bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/errors.h"
#include "lod/error_bounds.h"
#include "lod/lod_builder.h"
#include "lod/mesh_checker.h"
#include "lod/position_copy.h"
#include "lod/rippled_states.h"
#include "lod/surface_blocks.h"
#include "lod/tile_ranges.h"
#include "scene/scene.h"
#include "sim/cpu_solver.h"

namespace pond::lod_test {
namespace {

// "" when every node's world deviation from the rest grid lies in each tile holding it, and in the
// pyramid's cell over that tile; else the first node that does not.
std::string ranges_problem(const lod::TileRanges& r, const lod::NodePositions& p) {
  const double h = r.spacing();
  for (int y = 0; y < p.rows; ++y)
    for (int x = 0; x < p.cols; ++x) {
      const auto w = lod::world_position(p, y, x);
      const double d[3] = {w[0] - x * h, w[1], w[2] - y * h};
      for (int b = std::max(0, (y - 1) / lod::kTileCells); b <= std::min(y / lod::kTileCells, r.tiles_y() - 1); ++b)
        for (int a = std::max(0, (x - 1) / lod::kTileCells); a <= std::min(x / lod::kTileCells, r.tiles_x() - 1); ++a)
          for (int k = 0; k < r.levels(); ++k) {
            const lod::TileBounds& t = r.cell(k, a >> k, b >> k);
            const double lo[3] = {t.min_x, t.min_y, t.min_z}, hi[3] = {t.max_x, t.max_y, t.max_z};
            for (int c = 0; c < 3; ++c)
              if (!(lo[c] <= d[c] && d[c] <= hi[c]))
                return "node (" + std::to_string(y) + ", " + std::to_string(x) + ") axis " + std::to_string(c) +
                       " at level " + std::to_string(k) + ": " + std::to_string(d[c]) + " outside [" +
                       std::to_string(lo[c]) + ", " + std::to_string(hi[c]) + "]";
          }
      for (int c = 0; c < 3; ++c)
        if (std::abs(w[static_cast<std::size_t>(c)]) > r.largest()) return "largest is not the largest";
    }
  return "";
}

sim::CpuSolver rippled_solver(int rows, int cols, double spacing, std::uint32_t seed) {
  scene::Scene s;
  s.grid = {rows, cols, spacing};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 6; ++k) {
    sim::Perturbation p;
    p.row = u(rng) * (rows - 1), p.col = u(rng) * (cols - 1), p.radius = 1 + 2 * u(rng), p.amplitude = 2 * u(rng) - 1;
    s.perturbations.push_back(p);
  }
  sim::CpuSolver solver(sim::build_model(s), sim::Backend::scalar, 1);
  solver.track_tile_bounds(true);
  solver.advance(30);
  return solver;
}

TEST(TileRanges, HoldEveryNodeOfAFilesPositions) {
  for (auto [rows, cols] : {std::pair{2, 2}, {17, 17}, {18, 40}, {65, 65}, {100, 37}, {129, 300}}) {
    const std::vector<float> s = analytic_ripples(rows, cols, 4, 0.7, 7u + static_cast<std::uint32_t>(rows));
    const auto p = lod::interleaved_positions(s.data(), rows, cols);
    EXPECT_EQ(ranges_problem(lod::tile_ranges(p), p), "") << rows << "x" << cols;
  }
}

TEST(TileRanges, FromTheSolversBoundsHoldEveryNode) {
  for (auto [rows, cols, spacing] : {std::tuple{33, 33, 1.0}, {50, 71, 0.5}, {97, 40, 2.0}}) {
    sim::CpuSolver solver = rippled_solver(rows, cols, spacing, 11);
    const sim::WaterState& st = solver.state();
    const auto p = lod::grid_displacements(st.ux.data(), st.uy.data(), st.uz.data(), rows, cols, float(spacing));
    const lod::TileRanges r = lod::tile_ranges(solver.tile_bounds(), rows, cols, float(spacing));
    EXPECT_EQ(ranges_problem(r, p), "") << rows << "x" << cols;
  }
}

TEST(TileRanges, RejectNonFiniteInput) {
  std::vector<float> s = flat_pond(20, 20);
  s[6 * 45 + 1] = NAN;
  EXPECT_THROW(lod::tile_ranges(lod::interleaved_positions(s.data(), 20, 20)), InputError);
  std::vector<lod::TileBounds> bounds(4, lod::TileBounds{0, 0, 0, 0, 0, 0});
  bounds[3].max_y = INFINITY;
  EXPECT_THROW(lod::tile_ranges(bounds, 20, 20, 1.0f), InputError);
  EXPECT_THROW(lod::tile_ranges(bounds, 40, 40, 1.0f), InternalError);  // 9 tiles, not 4
}

// A node's range is the intersection of the tiles holding it (one, two or four), on grids whose
// last tiles are narrower, with random bounds.
TEST(TileRanges, AtNodeIsTheIntersectionOfItsTilesAndHullsTakeTheirUnion) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-3, 3);
  for (auto [rows, cols] : {std::pair{2, 2}, {17, 17}, {18, 40}, {65, 65}, {100, 37}}) {
    const int tx = static_cast<int>(shared::tiles_along(static_cast<shared::uint>(cols)));
    const int ty = static_cast<int>(shared::tiles_along(static_cast<shared::uint>(rows)));
    std::vector<lod::TileBounds> tiles(static_cast<std::size_t>(tx) * static_cast<std::size_t>(ty));
    for (lod::TileBounds& t : tiles) {
      const auto [x0, x1] = std::minmax({u(rng), u(rng)});  // the list's form: values, not references
      const auto [y0, y1] = std::minmax({u(rng), u(rng)});
      const auto [z0, z1] = std::minmax({u(rng), u(rng)});
      t = {x0, y0, z0, x1, y1, z1};
    }
    const lod::TileRanges r(rows, cols, 1.0, tiles, 1000.0f);
    int mismatches = 0;
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < cols; ++x) {
        std::array<float, 6> want{-INFINITY, -INFINITY, -INFINITY, INFINITY, INFINITY, INFINITY};
        for (int b = std::max(0, (y - 1) / lod::kTileCells); b <= std::min(y / lod::kTileCells, ty - 1); ++b)
          for (int a = std::max(0, (x - 1) / lod::kTileCells); a <= std::min(x / lod::kTileCells, tx - 1); ++a) {
            const lod::TileBounds& t = tiles[static_cast<std::size_t>(b) * static_cast<std::size_t>(tx) + static_cast<std::size_t>(a)];
            const std::array<float, 6> v{t.min_x, t.min_y, t.min_z, t.max_x, t.max_y, t.max_z};
            for (std::size_t k = 0; k < 6; ++k) want[k] = k < 3 ? std::max(want[k], v[k]) : std::min(want[k], v[k]);
          }
        const lod::TileBounds got = r.at_node(x, y);
        mismatches += std::array<float, 6>{got.min_x, got.min_y, got.min_z, got.max_x, got.max_y, got.max_z} != want;
      }
    EXPECT_EQ(mismatches, 0) << rows << "x" << cols;
    // The hull over several nodes: each coordinate's least lower and greatest upper bound.
    std::uniform_int_distribution<int> col(0, cols - 1), row(0, rows - 1);
    for (int k = 0; k < 200; ++k) {
      const lod::Point nodes[3] = {{col(rng), row(rng)}, {col(rng), row(rng)}, {col(rng), row(rng)}};
      const int n = 1 + k % 3;
      std::array<float, 6> want{INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
      for (int i = 0; i < n; ++i) {
        const lod::TileBounds t = r.at_node(nodes[i].x, nodes[i].y);
        const std::array<float, 6> v{t.min_x, t.min_y, t.min_z, t.max_x, t.max_y, t.max_z};
        for (std::size_t j = 0; j < 6; ++j) want[j] = j < 3 ? std::min(want[j], v[j]) : std::max(want[j], v[j]);
      }
      const lod::TileBounds got = r.hull_at(std::span(nodes, static_cast<std::size_t>(n)));
      EXPECT_EQ((std::array<float, 6>{got.min_x, got.min_y, got.min_z, got.max_x, got.max_y, got.max_z}), want)
          << rows << "x" << cols << " case " << k;
    }
  }
}

// The deviation of node n from t's interpolation (world units), n inside t (weights exact).
double miss(const lod::SurfaceBlock& b, const lod::Tri& t, lod::Point n) {
  const lod::Point a = t.apex, l = t.left, r = t.right;
  const double det = double(l.x - a.x) * (r.y - a.y) - double(l.y - a.y) * (r.x - a.x);
  const double wl = (double(n.x - a.x) * (r.y - a.y) - double(n.y - a.y) * (r.x - a.x)) / det;
  const double wr = (double(l.x - a.x) * (n.y - a.y) - double(l.y - a.y) * (n.x - a.x)) / det;
  const double wa = 1 - wl - wr;
  const auto id = [&](lod::Point q) { return b.grid->id(q); };
  double sum = 0;
  for (const std::vector<float>* c : {&b.x, &b.y, &b.z}) {
    const double e = (*c)[id(n)] - (wa * (*c)[id(a)] + wl * (*c)[id(l)] + wr * (*c)[id(r)]);
    sum += e * e;
  }
  return std::sqrt(sum);
}

bool inside(const lod::Tri& t, lod::Point n) {
  const auto side = [](lod::Point p, lod::Point q, lod::Point v) {
    return (long long)(q.x - p.x) * (v.y - p.y) - (long long)(q.y - p.y) * (v.x - p.x);
  };
  const long long s0 = side(t.apex, t.left, n), s1 = side(t.left, t.right, n), s2 = side(t.right, t.apex, n);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

// The node budgets' AVX2 copy gives the baseline's bits: views from above (the cone), grazing,
// from inside the pond and with half the pond behind the camera, on grids whose size leaves a tail
// after the last full vector.
TEST(NodeBudgets, AreTheSameBitsAtEveryWidth) {
  if (!lod::wide_budgets_available()) GTEST_SKIP() << "no AVX2 copy in this build, or no AVX2 on this CPU";
  for (auto [rows, cols] : {std::pair{129, 129}, {61, 83}}) {
    const std::vector<float> s = analytic_ripples(rows, cols, 5, 0.5, 7u);
    const auto p = lod::interleaved_positions(s.data(), rows, cols);
    const float largest = lod::tile_ranges(p).largest();
    const std::size_t n = static_cast<std::size_t>(rows) * cols;
    std::vector<float> x(n), y(n), z(n), wide(n), narrow(n);
    lod::copy_positions(p, x.data(), y.data(), z.data());
    const auto own = lod::soa_positions(x.data(), y.data(), z.data(), rows, cols);
    const double mx = cols / 2.0, mz = rows / 2.0;
    const lod::Camera views[] = {{{mx, 20, mz}, {mx, 0, mz}, 60, 1280, 720},
                                 {{mx, 1.5, -10}, {mx, 0.5, mz}, 50, 1280, 720},
                                 {{mx, 2, mz}, {mx + 30, 0, mz + 5}, 90, 640, 480},
                                 {{0, 20, 0}, {-30, 0, mz}, 60, 1280, 720}};
    for (const lod::Camera& cam : views) {
      const lod::BudgetTerms terms = lod::budget_terms(cam, 0.7, largest);
      lod::node_budgets(own, terms, wide.data(), true);
      lod::node_budgets(own, terms, narrow.data(), false);
      std::size_t in_view = 0;
      for (std::size_t k = 0; k < n; ++k) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(wide[k]), std::bit_cast<std::uint32_t>(narrow[k]))
            << rows << "x" << cols << " node " << k;
        in_view += std::isfinite(narrow[k]);
      }
      EXPECT_GT(in_view, 0u);  // each view sees part of the pond and leaves part out (both branches)
      EXPECT_LT(in_view, n);
    }
  }
}

// A world box's least budget (camera_budget.h: BoxBudget) is at most the budget of every point in it
// (5 x 5 x 5 of them, the corners among them), +infinity only when none is in view, and where every
// corner is in view as large as the least corner's budget: random boxes, from random cameras.
TEST(BoxBudget, IsTheLeastBudgetOfItsBox) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  int culled = 0, tight = 0, inside = 0;
  for (int k = 0; k < 400; ++k) {
    const lod::Camera cam{{100 * u(rng) - 50, 30 * u(rng) - 5, 100 * u(rng) - 50},
                          {100 * u(rng) - 50, 2 * u(rng) - 1, 100 * u(rng) - 50}, 30 + 80 * u(rng), 1280, 720};
    const lod::BudgetTerms terms = lod::budget_terms(cam, 1.0, 80.0f);
    const lod::BoxBudget box_budget(terms);
    for (int b = 0; b < 20; ++b) {
      std::array<double, 3> lo, hi;
      for (int i = 0; i < 3; ++i) {
        const double a = 100 * u(rng) - 50, w = (i == 1 ? 2 : 20) * u(rng);
        lo[i] = a, hi[i] = a + w;
      }
      std::vector<float> x, y, z;
      for (int i = 0; i < 125; ++i) {
        x.push_back(float(lo[0] + (hi[0] - lo[0]) * (i % 5) / 4.0));
        y.push_back(float(lo[1] + (hi[1] - lo[1]) * (i / 5 % 5) / 4.0));
        z.push_back(float(lo[2] + (hi[2] - lo[2]) * (i / 25) / 4.0));
      }
      std::vector<float> budget(x.size());
      lod::node_budgets(lod::soa_positions(x.data(), y.data(), z.data(), 5, 25), terms, budget.data());
      const double least = box_budget.least(lo, hi);
      for (double error : {0.0, 0.5 * least, least, std::nextafter(least, HUGE_VAL), 2 * least + 1e-3, 1e30})
        ASSERT_EQ(box_budget.allows(error, lo, hi), error <= least) << "camera " << k << " box " << b << " error " << error;
      if (box_budget.inside(lo, hi)) {  // every node in view: the budgets without the frustum's tests, the same bits
        ++inside;
        const lod::NodePositions nodes = lod::soa_positions(x.data(), y.data(), z.data(), 5, 25);
        for (bool wide : {false, true}) {
          std::vector<float> in_view(x.size());
          lod::node_budgets(nodes, terms, in_view.data(), wide, true);
          for (int i = 0; i < 125; ++i) {
            ASSERT_TRUE(std::isfinite(budget[i])) << "camera " << k << " box " << b << " point " << i;
            ASSERT_EQ(std::bit_cast<std::uint32_t>(in_view[i]), std::bit_cast<std::uint32_t>(budget[i]))
                << "camera " << k << " box " << b << " point " << i << " wide " << wide;
          }
        }
      }
      bool any_in_view = false, corners_in_view = true;
      double least_corner = HUGE_VAL;
      for (int i = 0; i < 125; ++i) {
        ASSERT_LE(least, double(budget[i]) * (1 + 1e-5)) << "camera " << k << " box " << b << " point " << i;
        any_in_view = any_in_view || std::isfinite(budget[i]);
        const bool corner = i % 5 % 4 == 0 && i / 5 % 5 % 4 == 0 && i / 25 % 4 == 0;
        if (corner) corners_in_view = corners_in_view && std::isfinite(budget[i]), least_corner = std::min(least_corner, double(budget[i]));
      }
      if (!any_in_view) culled += std::isinf(least);
      if (corners_in_view) {
        EXPECT_GE(least, least_corner * (1 - 1e-3) - 1e-4) << "camera " << k << " box " << b;
        ++tight;
      }
    }
  }
  EXPECT_GT(culled, 100);  // boxes out of view are culled, not only given small budgets
  EXPECT_GT(inside, 100);
  EXPECT_GT(tight, 100);
}

// The whole grid's nested bounds (error_bounds.h), as the builder makes them: for every vertex v and
// each triangle of v's diamond inside the grid, every node of the triangle but its corners is within
// bound(v) of its interpolation and has at least min_budget(v). Blocks have none: their triangles
// are scanned (surface_blocks.h).
TEST(SurfaceBlocks, NestedBoundsHoldOnTheWholeGridAndBlocksHaveNone) {
  for (auto [rows, cols] : {std::pair{129, 129}, {100, 77}, {65, 200}}) {
    const std::vector<float> s = analytic_ripples(rows, cols, 5, 0.5, 3u);
    const auto p = lod::interleaved_positions(s.data(), rows, cols);
    const lod::TileRanges ranges = lod::tile_ranges(p);
    const float largest = ranges.largest();
    const lod::Camera cam{{cols / 2.0, 40, -30}, {cols / 2.0, 0, rows / 2.0}, 60, 1280, 720};
    lod::SurfaceBlocks blocks(rows, cols);
    const lod::BudgetTerms terms = lod::budget_terms(cam, 1.0, largest);
    const lod::BoxBudget box_budget(terms);
    blocks.begin(p, terms, largest, ranges, box_budget);
    EXPECT_TRUE(blocks.block(0, 0).bounds.empty());
    const lod::SurfaceBlock& b = blocks.whole();
    ASSERT_EQ(b.bounds.size(), static_cast<std::size_t>(rows) * cols);
    int bounded = 0;
    long long held = 0;
    const bool full_check = rows != 65;  // node by node (a few million nodes a grid)
    for (int ly = 0; ly < rows; ++ly)
      for (int lx = 0; lx < cols; ++lx) {
        const lod::NestedBound& bound = b.bounds[b.grid->id({lx, ly})];
        if (!std::isfinite(bound.error)) continue;  // a corner, or a hypotenuse leaving the grid
        ++bounded;
        if (!full_check) continue;
        const lod::Diamond d = lod::GridHierarchy::diamond({lx, ly});
        for (lod::Point apex : d.parents) {
          const lod::Tri t = lod::oriented(apex, d.end0, d.end1);
          if (!b.grid->within_grid(t)) continue;  // the half outside the grid
          const lod::CellBox box = lod::box_of(t);
          for (int ny = box.y0; ny <= box.y1; ++ny)
            for (int nx = box.x0; nx <= box.x1; ++nx) {
              const lod::Point q{nx, ny};
              if (!inside(t, q) || q == t.apex || q == t.left || q == t.right) continue;  // corners: drawn
              ASSERT_LE(miss(b, t, q), double(bound.error) * (1 + 1e-6)) << "vertex " << lx << "," << ly << " node " << nx << "," << ny;
              ASSERT_GE(b.budget[b.grid->id(q)], bound.min_budget);
              ++held;
            }
        }
      }
    EXPECT_GT(bounded, rows * cols / 2) << rows << "x" << cols;
    if (full_check) {
      EXPECT_GT(held, static_cast<long long>(rows) * cols);
    }
    EXPECT_TRUE(blocks.block(1, 1).bounds.empty());
    // The next frame, on moved water: the whole grid's bounds are made again, as a new builder's.
    const std::vector<float> s2 = analytic_ripples(rows, cols, 5, 0.5, 4u);
    const auto p2 = lod::interleaved_positions(s2.data(), rows, cols);
    const lod::TileRanges ranges2 = lod::tile_ranges(p2);
    const float largest2 = ranges2.largest();
    lod::SurfaceBlocks fresh(rows, cols);
    const lod::BudgetTerms terms2 = lod::budget_terms(cam, 1.0, largest2);
    const lod::BoxBudget box_budget2(terms2);
    blocks.begin(p2, terms2, largest2, ranges2, box_budget2);
    fresh.begin(p2, terms2, largest2, ranges2, box_budget2);
    const auto& again = blocks.whole().bounds;
    const auto& made = fresh.whole().bounds;
    ASSERT_EQ(again.size(), made.size());
    for (std::size_t k = 0; k < made.size(); ++k)
      ASSERT_TRUE(std::bit_cast<std::uint64_t>(again[k]) == std::bit_cast<std::uint64_t>(made[k])) << "vertex " << k;
  }
}

// The live path: the solver's tile bounds and its displacements, as the renderer passes them.
TEST(LodBuilder, BuildsFromTheSolversTileBounds) {
  for (auto [rows, cols, spacing] : {std::tuple{129, 129, 1.0}, {90, 150, 0.5}}) {
    sim::CpuSolver solver = rippled_solver(rows, cols, spacing, 5);
    const sim::WaterState& st = solver.state();
    const auto p = lod::grid_displacements(st.ux.data(), st.uy.data(), st.uz.data(), rows, cols, float(spacing));
    const lod::TileRanges r = lod::tile_ranges(solver.tile_bounds(), rows, cols, float(spacing));
    const std::vector<float> world = sim::to_world_interleaved(st, solver.model());
    const double cx = (cols - 1) * spacing / 2, cz = (rows - 1) * spacing / 2;
    for (const CheckCamera& c : {CheckCamera{{cx, 20 * spacing, -10 * spacing}, {cx, 0, cz}, 60, 1280, 720},
                                 CheckCamera{{cx, 2 * spacing, cz - 3 * spacing}, {cx, 0, cz + 5}, 60, 640, 480}}) {
      lod::LodBuilder builder(rows, cols);
      std::vector<std::uint32_t> out(builder.max_indices());
      out.resize(builder.build(p, r, {c.eye, c.target, c.fovy_degrees, c.width, c.height}, 1.0, out));
      EXPECT_EQ(topology_problem(out, rows, cols), "");
      const ErrorReport e = screen_errors(out, rows, cols, world, c);
      EXPECT_EQ(e.uncovered, 0u);
      EXPECT_LE(e.max_error_px, 1.0);
      // The culling reads the drawn vertices' world positions from the builder (clipped fans' too).
      const std::span<const float> drawn[3] = {builder.world_x(), builder.world_y(), builder.world_z()};
      for (std::uint32_t v : out)
        for (std::size_t axis = 0; axis < 3; ++axis)
          ASSERT_EQ(drawn[axis][v], world[6 * std::size_t(v) + axis]) << rows << "x" << cols << " node " << v << " axis " << axis;
    }
  }
}

// Frame to frame: a view whose blocks and tests would cost more than one pass over the whole grid
// (a storm, seen whole: many tests, nearly every block) makes the next build read the whole grid,
// and a view needing few blocks turns it back. Rain over the same pond, with a quarter of the
// tests, stays in blocks. Every build holds the contract either way.
TEST(LodBuilder, ReadsTheWholeGridWhereThatCostsLess) {
  const int side = 257;
  const CheckCamera whole_pond{{128, 35, -20}, {128, 0, 110}, 60, 1280, 720};
  const CheckCamera one_corner{{10, 3, 10}, {0, 0, 0}, 40, 640, 480};
  for (const double amplitude : {1.0, 0.1}) {
    const bool storm = amplitude == 1.0;
    const std::vector<float> s = simulated_pond(side, side, 412, 20, 15, 1, amplitude);
    const auto p = lod::interleaved_positions(s.data(), side, side);
    const lod::TileRanges r = lod::tile_ranges(p);
    lod::LodBuilder builder(side, side);
    std::vector<std::uint32_t> out(builder.max_indices());
    const auto build = [&](const CheckCamera& c, const std::string& what) {
      std::vector<std::uint32_t> tris(out.begin(),
                                      out.begin() + static_cast<std::ptrdiff_t>(builder.build(
                                                        p, r, {c.eye, c.target, c.fovy_degrees, c.width, c.height}, 1.0, out)));
      EXPECT_EQ(topology_problem(tris, side, side), "") << what;
      const ErrorReport e = screen_errors(tris, side, side, s, c);
      EXPECT_EQ(e.uncovered, 0u) << what;
      EXPECT_LE(e.max_error_px, 1.0) << what;
      for (std::uint32_t v : tris) {  // what the frame's culling reads, either way
        EXPECT_EQ(builder.world_x()[v], s[6 * std::size_t(v)]) << what;
        EXPECT_EQ(builder.world_z()[v], s[6 * std::size_t(v) + 2]) << what;
      }
      return tris;
    };
    const std::string what = storm ? "storm: " : "rain: ";
    const std::vector<std::uint32_t> in_blocks = build(whole_pond, what + "first build");
    EXPECT_FALSE(builder.stats().whole) << what;
    const std::vector<std::uint32_t> next = build(whole_pond, what + "second build");
    EXPECT_EQ(builder.stats().whole, storm) << what;
    EXPECT_EQ(next, in_blocks) << what;  // the same exact tests, either way: the same mesh
    if (!storm) continue;
    build(one_corner, what + "the corner, after the whole pond");
    EXPECT_TRUE(builder.stats().whole);
    build(one_corner, what + "the corner again");
    EXPECT_FALSE(builder.stats().whole);
    EXPECT_LT(builder.stats().blocks, 20u);
  }
}

}  // namespace
}  // namespace pond::lod_test
