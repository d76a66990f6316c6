// Bodies in the water (sim/bodies.h, sim/contact.h): no node inside a kinematic body after a
// substep, the same bits on every backend and thread count, and the wake of a dragged sphere. The
// floating bodies' laws are tested in floating_test.cpp.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "sim/backends.h"
#include "sim/contact.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"
#include "shifted_pool.h"
#include "test_util.h"

namespace pond {
namespace {

using scene::Scene;
using sim::Backend;
using sim::CpuSolver;
using sim::NodeKind;
using sim::PathKey;
using sim::WaterModel;
using sim::WaterState;

using test::ball;

// A mixed scene: a kinematic sphere crossing the pool, a ball dropped in, a ball on the water, two
// balls that collide, an island and a splash.
Scene mixed_scene(int rows, int cols, int substeps) {
  Scene s = test::grid_scene(rows, cols);
  s.physics.substeps = substeps;
  s.constraints.push_back({NodeKind::fixed, rows / 2 + 4, rows / 2 + 7, cols / 2, cols / 2 + 5});
  s.perturbations.push_back(test::splash(rows / 3.0, cols / 3.0, 2, 1, 5));
  const double z = rows / 2.0;
  s.bodies.push_back(test::kinematic(3.0, {PathKey{0, {6.0, 0.5, z}}, PathKey{120, {cols - 7.0, 0.5, z}},
                                   PathKey{160, {cols - 7.0, -1.0, z - 8}}}));
  s.bodies.push_back(ball({cols / 4.0, 3.0, rows / 4.0}, 2.0, 0.9, {0.0, -0.3, 0.0}));
  s.bodies.push_back(ball({0.7 * cols, 2.0, 0.75 * rows}, 2.5, 0.3, {0.05, 0.0, -0.02}));
  s.bodies.push_back(ball({cols / 2.0 - 10, 0.5, rows / 4.0}, 1.5, 0.5, {0.4, 0.0, 0.05}));
  s.bodies.push_back(ball({cols / 2.0 + 6, 0.0, rows / 4.0 + 1}, 2.0, 0.7, {-0.3, 0.0, 0.0}));
  return s;
}

// In grid units, double precision: how far the deepest non-fixed node lies inside a kinematic body
// (floating ones let the water through), as a fraction of its radius (0: none inside), and how
// many nodes touch a kinematic body's surface.
struct Penetration {
  double deepest = 0;
  int touching = 0;
};
Penetration penetration(const WaterState& s, const WaterModel& m) {
  Penetration p;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (m.bodies[b].floating()) continue;
    const double r = m.bodies[b].constants.radius;
    for (std::size_t n = 0; n < s.nodes(); ++n) {
      if (m.kinds[n] == static_cast<std::uint8_t>(NodeKind::fixed)) continue;
      const double i = static_cast<double>(n / m.cols), j = static_cast<double>(n % m.cols);
      const double dx = j + s.ux[n] - s.bodies[b].x, dy = s.uy[n] - s.bodies[b].y, dz = i + s.uz[n] - s.bodies[b].z;
      const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
      p.deepest = std::max(p.deepest, (r - d) / r);
      if (std::fabs(d - r) < 1e-4 * r) ++p.touching;
    }
  }
  return p;
}

bool same_bits(const WaterState& a, const WaterState& b) {
  return a.bodies.size() == b.bodies.size() &&
         std::memcmp(a.bodies.data(), b.bodies.data(), a.bodies.size() * sizeof(sim::BodyState)) == 0;
}

TEST(Bodies, NoNodeIsInsideABodyAfterAnySubstep) {
  // One substep per step: the state after every step is the state after every substep.
  const WaterModel m = sim::build_model(mixed_scene(41, 67, 1));
  for (Backend backend : test::available_backends()) {
    CpuSolver solver(m, backend, 1);
    int touching_steps = 0;
    for (int step = 0; step < 200; ++step) {
      solver.advance(1);
      const Penetration p = penetration(solver.state(), m);
      ASSERT_LT(p.deepest, 1e-5) << sim::backend_name(backend) << ", after step " << step + 1;
      touching_steps += p.touching > 0;
    }
    EXPECT_GT(touching_steps, 150) << "the bodies must really touch the water";
  }
}

TEST(Bodies, EveryBackendAndThreadCountGivesTheSameBits) {
  for (int cols : {64, 67}) {  // a multiple of 4 and not
    for (int substeps : {1, 3}) {
      const WaterModel m = sim::build_model(mixed_scene(48, cols, substeps));
      CpuSolver reference(m, Backend::scalar, 1);
      reference.advance(180);
      for (Backend backend : test::available_backends())
        for (int threads : {1, 2}) {
          CpuSolver solver(m, backend, threads);
          solver.advance(180);
          EXPECT_EQ(sim::state_hash(solver.state(), m), sim::state_hash(reference.state(), m))
              << cols << " cols, " << substeps << " substeps, " << sim::backend_name(backend) << " x " << threads;
          EXPECT_TRUE(same_bits(solver.state(), reference.state()));
        }
    }
  }
}

// A node pulled sideways by more than a spacing past radius + 1 (tests/sim/shifted_pool.h) is
// still found by its actual position and pushed out, on every backend, with the same bits.
TEST(Bodies, ANodePulledFarSidewaysIsStillPushedOut) {
  const test::ShiftedPool pool = test::shifted_pool();
  const WaterModel& m = pool.model;
  const std::size_t node = static_cast<std::size_t>(test::ShiftedPool::kRow) * m.cols + test::ShiftedPool::kCol;
  // A footprint of radius + 1 around the ball ends at column ceil(20 + 3) + 1 = 24.
  ASSERT_GT(test::ShiftedPool::kCol, 24 + 1);
  ASSERT_LT(std::fabs(test::ShiftedPool::kCol + test::ShiftedPool::kShift - 20.0), 1.0) << "the node is under the ball";
  WaterState narrow = pool.state;  // what a footprint of radius + 1 (a reach of 0) leaves
  sim::resolve_contacts(narrow, m, 0, 0, 0.0f);
  EXPECT_GT(penetration(narrow, m).deepest, 0.5) << "a footprint of radius + 1 must miss the node";
  CpuSolver reference(m, Backend::scalar, 1);
  reference.set_state(pool.state, 0);
  reference.advance(1);
  EXPECT_LT(penetration(reference.state(), m).deepest, 1e-5);
  // Pushed to the lower cap: 0.5 - sqrt(9 - 0.5^2), not left at -0.2 inside the ball.
  EXPECT_NEAR(reference.state().uy[node], 0.5 - std::sqrt(9.0 - 0.25), 1e-5);
  EXPECT_EQ(reference.state().vy[node], reference.state().bodies[0].vy) << "the node takes the body's velocity";
  for (Backend backend : test::available_backends())
    for (int threads : {1, 2}) {
      CpuSolver solver(m, backend, threads);
      solver.set_state(pool.state, 0);
      solver.advance(1);
      EXPECT_EQ(sim::state_hash(solver.state(), m), sim::state_hash(reference.state(), m))
          << sim::backend_name(backend) << " x " << threads;
      EXPECT_TRUE(same_bits(solver.state(), reference.state())) << sim::backend_name(backend) << " x " << threads;
    }
}

TEST(Bodies, ADraggedSphereLeavesAWakeBehindAndNotAhead) {
  Scene s = test::grid_scene(33, 161);
  s.bodies.push_back(test::kinematic(3.0, {PathKey{0, {10.0, 0.5, 16.0}}, PathKey{200, {150.0, 0.5, 16.0}}}));
  const WaterModel m = sim::build_model(s);
  CpuSolver solver(m, Backend::scalar, 1);
  solver.advance(100);  // the sphere is at x = 80
  const double x = solver.state().bodies[0].x;
  ASSERT_NEAR(x, 80.0, 1e-3);
  double behind = 0, ahead = 0;
  for (std::size_t n = 0; n < solver.state().nodes(); ++n) {
    const double j = static_cast<double>(n % m.cols), y = solver.state().uy[n];
    if (j < x - 6) behind += y * y;
    if (j > x + 6) ahead += y * y;
  }
  EXPECT_GT(behind, 1.0) << "a wake";
  EXPECT_LT(ahead, 0.01 * behind) << "behind " << behind << ", ahead " << ahead;
}

}  // namespace
}  // namespace pond
