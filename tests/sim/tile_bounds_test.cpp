// The tile bounds (shared/tile_bounds.h) the step kernels emit: after every advance() of random
// scenes every node lies within its tiles' bounds and every bound is some node's value; the same
// bits on every backend and thread count, equal to the reference; and the state's bits unchanged.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"
#include "sim/tile_bounds.h"
#include "test_util.h"

namespace pond::sim {
namespace {

using scene::Scene;

// Checks the bounds of tile (a, b) against its nodes: each within, each bound attained, NaN-free,
// no -0 bound. Returns "" or what is wrong.
std::string check_tile(std::span<const TileBounds> bounds, const WaterState& s, const TileGrid& g, int a, int b) {
  const TileBounds& t = bounds[static_cast<std::size_t>(b) * g.tiles_x + a];
  const float lo[3] = {t.min_x, t.min_y, t.min_z}, hi[3] = {t.max_x, t.max_y, t.max_z};
  const float* u[3] = {s.ux.data(), s.uy.data(), s.uz.data()};
  const std::string where = "tile (" + std::to_string(a) + ", " + std::to_string(b) + ") axis ";
  for (int axis = 0; axis < 3; ++axis) {
    bool lo_seen = false, hi_seen = false;
    for (int i = 16 * b; i <= std::min(16 * b + 16, g.rows - 1); ++i)
      for (int j = 16 * a; j <= std::min(16 * a + 16, g.cols - 1); ++j) {
        const float v = u[axis][static_cast<std::size_t>(i) * g.cols + j];
        if (!(lo[axis] <= v && v <= hi[axis]))
          return where + std::to_string(axis) + ": node (" + std::to_string(i) + ", " + std::to_string(j) +
                 ") at " + std::to_string(v) + " outside [" + std::to_string(lo[axis]) + ", " +
                 std::to_string(hi[axis]) + "]";
        lo_seen = lo_seen || v == lo[axis];
        hi_seen = hi_seen || v == hi[axis];
      }
    if (!lo_seen || !hi_seen) return where + std::to_string(axis) + ": a bound no node attains";
    for (float bound : {lo[axis], hi[axis]})
      if (std::bit_cast<std::uint32_t>(bound) == 0x80000000u) return where + std::to_string(axis) + ": -0";
  }
  return "";
}

std::string check_all(CpuSolver& solver) {
  const TileGrid& g = solver.tile_grid();
  if (solver.tile_bounds().size() != g.tiles()) return "no bounds";
  for (int b = 0; b < g.tiles_y; ++b)
    for (int a = 0; a < g.tiles_x; ++a)
      if (std::string e = check_tile(solver.tile_bounds(), solver.state(), g, a, b); !e.empty()) return e;
  if (std::memcmp(solver.tile_bounds().data(), compute_tile_bounds(solver.state(), g).data(),
                  g.tiles() * sizeof(TileBounds)) != 0)
    return "not the reference's bits";
  return "";
}

// A random scene: a grid of 2 to 90 rows and 2 to 300 columns (one in four wider than the 128
// columns AVX-512's pass reads as one group, tile_kernel.h), an island and a vertical-only strip,
// splashes of every kind at random steps, and on larger grids a kinematic sphere crossing the
// water and balls.
Scene random_scene(std::mt19937& rng) {
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto integer = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  const int sizes[] = {2, 3, 16, 17, 18, 33, 47, 49, 64, 65, 90};
  const int rows = integer(0, 1) ? sizes[integer(0, 10)] : integer(2, 90);
  const int wide[] = {129, 145, 257, 273, 300};
  const int cols = integer(0, 3) == 0 ? wide[integer(0, 4)] : integer(0, 1) ? sizes[integer(0, 10)] : integer(2, 90);
  Scene s = test::grid_scene(rows, cols, integer(0, 2) ? NodeKind::fixed : NodeKind::free);
  if (rows > 10 && cols > 10) {
    const int r = integer(1, rows - 6), c = integer(1, cols - 6);
    s.constraints.push_back({NodeKind::fixed, r, r + integer(0, 4), c, c + integer(0, 4)});
    const int v = integer(0, rows - 1);
    s.constraints.push_back({NodeKind::vertical, v, v, 0, cols - 1});
  }
  for (int k = integer(1, 6); k > 0; --k) {
    const auto target = integer(0, 1) ? PerturbTarget::position : PerturbTarget::velocity;
    const auto mode = integer(0, 3) ? PerturbMode::add : PerturbMode::set;
    s.perturbations.push_back(test::splash(uniform(0, rows - 1), uniform(0, cols - 1), uniform(0.8, 3), uniform(-1, 1),
                                           integer(0, 30), target, mode));
  }
  if (rows >= 24 && cols >= 24) {
    const double z = uniform(6, rows - 7);
    s.bodies.push_back(test::kinematic(uniform(1.5, 3), {PathKey{0, {4.0, 0.5, z}}, PathKey{40, {cols - 5.0, 0.0, z}}}));
    s.bodies.push_back(test::ball({uniform(5, cols - 6), 2.0, uniform(5, rows - 6)}, 1.5, uniform(0.3, 0.9)));
  }
  return s;
}

// One to three substeps a step and one to three steps an advance(): the bounds come from the last
// substep of each advance() (its kernel and contact), the earlier ones emit none.
TEST(TileBounds, HoldAfterEveryAdvanceOfRandomScenes) {
  for (unsigned seed = 1; seed <= 24; ++seed) {
    std::mt19937 rng(seed);
    Scene s = random_scene(rng);
    s.physics.substeps = 1 + static_cast<int>(seed % 3);
    const WaterModel m = build_model(s);
    CpuSolver solver(m, test::available_backends().back(), 1);
    solver.track_tile_bounds(true);
    std::mt19937 splashes(seed + 1000);
    for (int step = 0; step < 50; ++step) {
      solver.advance(1 + (step + static_cast<int>(seed)) % 3);
      ASSERT_EQ(check_all(solver), "") << "seed " << seed << " (" << m.rows << "x" << m.cols << ", "
                                       << m.substeps << " substeps), advance " << step;
      if (step % 7 == 3) {  // a splash now, between steps, as the demo's clicks and rain
        std::uniform_real_distribution<double> at(0, 1);
        const Perturbation p = test::splash(at(splashes) * (m.rows - 1), at(splashes) * (m.cols - 1), 1.5,
                                            at(splashes) - 0.5, 0, PerturbTarget::position,
                                            step % 2 ? PerturbMode::add : PerturbMode::set);
        solver.perturb(tabulate(p, m));
        ASSERT_EQ(check_all(solver), "") << "seed " << seed << ", splash after step " << step;
      }
    }
  }
}

TEST(TileBounds, TrackedFromAnyState) {
  Scene s = test::grid_scene(37, 53);
  s.perturbations.push_back(test::splash(18, 26, 3, 1));
  const WaterModel m = build_model(s);
  CpuSolver solver(m, Backend::scalar, 1);
  solver.advance(10);
  EXPECT_TRUE(solver.tile_bounds().empty());
  solver.track_tile_bounds(true);
  EXPECT_EQ(check_all(solver), "");
  CpuSolver other(m, Backend::scalar, 1);
  other.track_tile_bounds(true);
  other.set_state(solver.state(), solver.steps_done());
  EXPECT_EQ(check_all(other), "");
  solver.track_tile_bounds(false);
  EXPECT_TRUE(solver.tile_bounds().empty());
}

// -0 and +0 are one value, its bound +0, whichever comes first; NaN is skipped, in the reference
// and in the merge of the threads' partial tile rows.
TEST(TileBounds, ZerosAreOneValueAndNaNIsSkipped) {
  const TileGrid g(3, 3);
  WaterState s(9);
  const float nan = std::nanf("");
  for (std::size_t n = 0; n < 9; ++n) {
    s.ux[n] = n % 2 ? -0.0f : 0.0f;
    s.uy[n] = n % 2 ? 0.0f : -0.0f;
    s.uz[n] = n == 4 ? nan : static_cast<float>(n) - 4.0f;
  }
  const TileBounds t = compute_tile_bounds(s, g)[0];
  for (float bound : {t.min_x, t.max_x, t.min_y, t.max_y}) EXPECT_EQ(std::bit_cast<std::uint32_t>(bound), 0u);
  EXPECT_EQ(t.min_z, -4.0f);
  EXPECT_EQ(t.max_z, 4.0f);
  for (bool minus_first : {false, true}) {
    const float a = minus_first ? -0.0f : 0.0f, b = minus_first ? 0.0f : -0.0f;
    const std::vector<TileBounds> first{{a, a, nan, a, a, nan}}, second{{b, b, 1.0f, b, b, 1.0f}};
    std::vector<TileBounds> merged(1);
    merge_tile_rows(merged, g, {{0, 0}, {0, 0}}, {first.data(), second.data()});
    for (float bound : {merged[0].min_x, merged[0].max_x}) EXPECT_EQ(std::bit_cast<std::uint32_t>(bound), 0u);
    EXPECT_EQ(merged[0].min_z, 1.0f);
    EXPECT_EQ(merged[0].max_z, 1.0f);
  }
}

// The bounds' bytes after every step of one run.
std::vector<std::vector<TileBounds>> run_bounds(const WaterModel& m, Backend b, int threads, std::uint64_t& hash) {
  CpuSolver solver(m, b, threads);
  solver.track_tile_bounds(true);
  std::vector<std::vector<TileBounds>> out;
  for (int step = 0; step < 12; ++step) {
    solver.advance(1);
    out.emplace_back(solver.tile_bounds().begin(), solver.tile_bounds().end());
    EXPECT_EQ(check_all(solver), "") << backend_name(b) << " x " << threads << ", step " << step;
  }
  hash = state_hash(solver.state(), m);
  return out;
}

bool same_bits(const std::vector<std::vector<TileBounds>>& a, const std::vector<std::vector<TileBounds>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k].size() != b[k].size() || std::memcmp(a[k].data(), b[k].data(), a[k].size() * sizeof(TileBounds)) != 0)
      return false;
  return true;
}

// Grids large enough for two or three threads' row ranges (cpu_solver.cpp), whose borders fall
// inside a tile row and on one, and rows longer than a kernel's column block: 1100 columns, and
// 1025, whose last column alone is the second block.
TEST(TileBounds, SameBitsOnEveryBackendAndThreadCount) {
  for (auto [rows, cols] : {std::pair{181, 203}, std::pair{64, 520}, std::pair{33, 1100}, std::pair{40, 1025}}) {
    Scene s = test::grid_scene(rows, cols, NodeKind::free);
    s.physics.substeps = 2;
    s.perturbations.push_back(test::splash(rows / 2.0, cols / 3.0, 3, 1));
    s.perturbations.push_back(test::splash(rows / 3.0, cols - 3.0, 2, -0.7, 0, PerturbTarget::position));
    s.bodies.push_back(test::kinematic(2.5, {PathKey{0, {6.0, 0.5, rows / 2.0}}, PathKey{12, {30.0, 0.5, rows / 2.0}}}));
    const WaterModel m = build_model(s);
    std::uint64_t untracked_hash = 0;
    {
      CpuSolver solver(m, Backend::scalar, 1);
      solver.advance(12);
      untracked_hash = state_hash(solver.state(), m);
    }
    std::uint64_t hash = 0;
    const auto reference = run_bounds(m, Backend::scalar, 1, hash);
    EXPECT_EQ(hash, untracked_hash) << rows << "x" << cols << ": the bounds changed the step's bits";
    for (Backend b : test::available_backends())
      for (int threads : {1, 2, 3}) {
        const auto bounds = run_bounds(m, b, threads, hash);
        EXPECT_TRUE(same_bits(bounds, reference)) << rows << "x" << cols << " " << backend_name(b) << " x " << threads;
        EXPECT_EQ(hash, untracked_hash) << rows << "x" << cols << " " << backend_name(b) << " x " << threads;
      }
    CpuSolver solver(m, Backend::scalar, 2);
    EXPECT_GT(solver.threads(), 1) << rows << "x" << cols << ": too small to split";
  }
}

}  // namespace
}  // namespace pond::sim
