// The GPU's tile bounds (shared/tile_bounds.h; GpuSolver::track_tile_bounds): on random scenes of
// sizes that are and are not 16k + 1 nodes a side, one and two normals workgroups across a row,
// with splashes and bodies, after every frame they have the bits of sim::compute_tile_bounds of
// the GPU's own state and of the CPU solver's tracked bounds (exact math: the same state); from
// set states with signed zeros, denormals and NaNs too. Off by default and off again on request.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "gpu/gpu_solver.h"
#include "gpu_fixture.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"
#include "sim/test_util.h"
#include "sim/tile_bounds.h"

namespace pond::test {
namespace {

using sim::TileBounds;

// "" when `got` has the bits of `want`, else the first differing tile and both.
std::string compare(std::span<const TileBounds> got, std::span<const TileBounds> want, const sim::TileGrid& g) {
  if (got.size() != want.size())
    return "size " + std::to_string(got.size()) + ", expected " + std::to_string(want.size());
  for (std::size_t t = 0; t < got.size(); ++t)
    if (std::memcmp(&got[t], &want[t], sizeof(TileBounds)) != 0) {
      const TileBounds& a = got[t];
      const TileBounds& b = want[t];
      char text[400];
      std::snprintf(text, sizeof text,
                    "tile (%d, %d): min %a %a %a max %a %a %a, expected min %a %a %a max %a %a %a",
                    static_cast<int>(t % g.tiles_x), static_cast<int>(t / g.tiles_x), a.min_x, a.min_y, a.min_z,
                    a.max_x, a.max_y, a.max_z, b.min_x, b.min_y, b.min_z, b.max_x, b.max_y, b.max_z);
      return text;
    }
  return "";
}

// A scene of `rows` x `cols`: an island and a vertical-only row where there is room, splashes of
// every kind at random steps, and on grids of 24 or more a kinematic sphere crossing and a ball.
scene::Scene random_scene(int rows, int cols, std::mt19937& rng) {
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto integer = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  scene::Scene s = grid_scene(rows, cols, integer(0, 2) ? sim::NodeKind::fixed : sim::NodeKind::free);
  if (rows > 10 && cols > 10) {
    const int r = integer(1, rows - 6), c = integer(1, cols - 6);
    s.constraints.push_back({sim::NodeKind::fixed, r, r + integer(0, 4), c, c + integer(0, 4)});
    const int v = integer(0, rows - 1);
    s.constraints.push_back({sim::NodeKind::vertical, v, v, 0, cols - 1});
  }
  for (int k = integer(1, 5); k > 0; --k)
    s.perturbations.push_back(splash(uniform(0, rows - 1), uniform(0, cols - 1), uniform(0.8, 3), uniform(-1, 1),
                                     integer(0, 20), integer(0, 1) ? sim::PerturbTarget::position
                                                                   : sim::PerturbTarget::velocity,
                                     integer(0, 3) ? sim::PerturbMode::add : sim::PerturbMode::set));
  if (rows >= 24 && cols >= 24) {
    const double z = uniform(6, rows - 7);
    s.bodies.push_back(kinematic(uniform(1.5, 3), {sim::PathKey{0, {4.0, 0.5, z}}, sim::PathKey{30, {cols - 5.0, 0.0, z}}}));
    s.bodies.push_back(ball({uniform(5, cols - 6), 2.0, uniform(5, rows - 6)}, 1.5, uniform(0.3, 0.9)));
  }
  return s;
}

struct Size {
  int rows, cols;
};

// 16k + 1 (17, 129) and not (50, 37, 65, 200, 16, 2); 301 columns: two normals workgroups, a tile
// across their border.
const Size kSizes[] = {{50, 37}, {129, 129}, {65, 200}, {17, 33}, {16, 16}, {2, 2}, {40, 301}, {3, 97}};

TEST_F(GpuTest, TileBoundsEqualTheReferenceAndTheCpuAfterEveryFrame) {
  unsigned seed = 1;
  for (const Size size : kSizes)
    for (const bool drawn : {false, true}) {
      std::mt19937 rng(seed++);
      const sim::WaterModel m = sim::build_model(random_scene(size.rows, size.cols, rng));
      const std::string what = std::to_string(m.rows) + "x" + std::to_string(m.cols) + (drawn ? " drawn" : "");
      gpu::GpuSolver gpu(ctx(), m, drawn);
      sim::CpuSolver cpu(m, sim::Backend::scalar, 1);
      gpu.track_tile_bounds(true);
      cpu.track_tile_bounds(true);
      const sim::TileGrid& g = gpu.tile_grid();
      ASSERT_EQ(compare(gpu.tile_bounds(), cpu.tile_bounds(), g), "") << what << " at rest";
      bool moved = false;
      int frame = 0;
      for (const std::int64_t steps : {1, 4, 0, 7, 2, 13, 1, 30}) {
        if (frame++ % 3 == 1) {  // a splash between frames, as the demo's clicks and rain
          std::uniform_real_distribution<double> at(0, 1);
          const sim::PerturbationTable p = sim::tabulate(
              splash(at(rng) * (m.rows - 1), at(rng) * (m.cols - 1), 1.5, 0.6, 0, sim::PerturbTarget::position), m);
          gpu.perturb(p);
          cpu.perturb(p);
        }
        gpu.advance(steps);
        cpu.advance(steps);
        const sim::WaterState state = gpu.read_state();
        ASSERT_EQ(sim::state_hash(state, m), sim::state_hash(cpu.state(), m)) << what << ": not the CPU's state";
        const std::span<const TileBounds> bounds = gpu.tile_bounds();
        EXPECT_EQ(compare(bounds, sim::compute_tile_bounds(state, g), g), "") << what << " after " << cpu.steps_done();
        EXPECT_EQ(compare(bounds, cpu.tile_bounds(), g), "") << what << " after " << cpu.steps_done();
        for (const TileBounds& t : bounds) moved = moved || t.max_y > t.min_y;
      }
      EXPECT_TRUE(moved) << what << ": still water proves little";
    }
}

// Off by default (no buffer, no bounds); on gives the current state's at once; off again drops them.
TEST_F(GpuTest, TileBoundsAreTrackedOnlyOnRequest) {
  scene::Scene s = grid_scene(37, 53);
  s.perturbations.push_back(splash(18, 26, 3, 1));
  const sim::WaterModel m = sim::build_model(s);
  gpu::GpuSolver gpu(ctx(), m);
  gpu.advance(10);
  EXPECT_TRUE(gpu.tile_bounds().empty());
  EXPECT_EQ(gpu.tile_bounds_buffer(), nullptr);
  gpu.track_tile_bounds(true);
  ASSERT_NE(gpu.tile_bounds_buffer(), nullptr);
  EXPECT_EQ(gpu.tile_bounds_buffer()->size, gpu.tile_grid().tiles() * sizeof(TileBounds));
  EXPECT_EQ(compare(gpu.tile_bounds(), sim::compute_tile_bounds(gpu.read_state(), gpu.tile_grid()), gpu.tile_grid()), "");
  gpu.track_tile_bounds(false);
  EXPECT_TRUE(gpu.tile_bounds().empty());
  EXPECT_EQ(gpu.tile_bounds_buffer(), nullptr);
  gpu.advance(5);
  gpu.track_tile_bounds(true);
  EXPECT_EQ(compare(gpu.tile_bounds(), sim::compute_tile_bounds(gpu.read_state(), gpu.tile_grid()), gpu.tile_grid()), "");
}

// A set state (no step): its bounds from the GPU and the reference, as bits.
std::string set_state_bounds_differ(const gpu::Context& ctx, const sim::WaterModel& m, const sim::WaterState& s) {
  gpu::GpuSolver gpu(ctx, m);
  gpu.track_tile_bounds(true);
  gpu.set_state(s, 0);
  return compare(gpu.tile_bounds(), sim::compute_tile_bounds(s, gpu.tile_grid()), gpu.tile_grid());
}

// -0 and +0 are one value and a zero bound is +0, whichever the tile meets first; denormals are
// values (both sides keep them: gpu/float_policy.h).
TEST_F(GpuTest, TileBoundsOfSignedZerosAndDenormalsAreTheReferences) {
  const sim::WaterModel m = sim::build_model(grid_scene(33, 50));
  sim::WaterState s(m.nodes());
  const float denormal = std::bit_cast<float>(0x00000123u);
  for (std::size_t n = 0; n < s.nodes(); ++n) {
    const std::size_t i = n / 50, j = n % 50;
    s.ux[n] = (i + j) % 2 ? -0.0f : 0.0f;                  // both zeros in every tile
    s.uy[n] = j < 17 ? -0.0f : (j == 40 ? denormal : 0.0f);  // a tile of -0 only; a denormal
    s.uz[n] = i < 16 ? -static_cast<float>(j % 3) * 0.25f - 0.0f : -0.0f;  // -0 as the maximum
    if (i == 20 && j == 5) s.uz[n] = -denormal;
  }
  EXPECT_EQ(set_state_bounds_differ(ctx(), m, s), "");
  const std::vector<TileBounds> want = sim::compute_tile_bounds(s, sim::TileGrid(m.rows, m.cols));
  for (const TileBounds& t : want)
    for (const float b : {t.min_x, t.max_x, t.min_y, t.max_y, t.min_z, t.max_z})
      EXPECT_NE(std::bit_cast<std::uint32_t>(b), 0x80000000u) << "the reference kept a -0";
}

// A NaN displacement is skipped; a tile of NaNs only has +inf as its minimum and -inf as its
// maximum (the shaders declare SignedZeroInfNanPreserve, so their compares see NaN).
TEST_F(GpuTest, TileBoundsSkipNaNAsTheReference) {
  const sim::WaterModel m = sim::build_model(grid_scene(40, 21));
  sim::WaterState s(m.nodes());
  const float nan = std::nanf("");
  for (std::size_t n = 0; n < s.nodes(); ++n) {
    const std::size_t i = n / 21, j = n % 21;
    s.ux[n] = (i * 7 + j) % 5 ? static_cast<float>(j) * 0.125f - 1.0f : nan;
    s.uy[n] = i >= 16 && i <= 32 ? nan : static_cast<float>(i) * -0.5f;  // tile row 1: only NaN
    s.uz[n] = i == 3 && j == 4 ? 2.0f : (j % 2 ? nan : -0.0f);
  }
  EXPECT_EQ(set_state_bounds_differ(ctx(), m, s), "");
}

}  // namespace
}  // namespace pond::test
