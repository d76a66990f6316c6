// Bodies in the water (sim/bodies.h, sim/contact.h): no node inside a body after a substep, the
// same bits on every backend, momentum kept by the contact, a floating ball carried by the
// membrane's springs, and the wake of a dragged sphere.
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
using sim::BodyMotion;
using sim::BodySpec;
using sim::CpuSolver;
using sim::NodeKind;
using sim::PathKey;
using sim::WaterModel;
using sim::WaterState;

BodySpec ball(std::array<double, 3> position, double radius, double mass, std::array<double, 3> velocity = {}) {
  BodySpec b;
  b.motion = BodyMotion::floating;
  b.position = position;
  b.velocity = velocity;
  b.radius = radius;
  b.mass = mass;
  return b;
}

BodySpec dragged(double radius, std::vector<PathKey> path) {
  BodySpec b;
  b.motion = BodyMotion::kinematic;
  b.radius = radius;
  b.path = std::move(path);
  return b;
}

// A mixed scene: a kinematic sphere crossing the pool, a ball dropped in, a ball at rest on the
// water, an island and a splash.
Scene mixed_scene(int rows, int cols, int substeps) {
  Scene s = test::grid_scene(rows, cols);
  s.physics.substeps = substeps;
  s.constraints.push_back({NodeKind::fixed, rows / 2 + 4, rows / 2 + 7, cols / 2, cols / 2 + 5});
  s.perturbations.push_back(test::splash(rows / 3.0, cols / 3.0, 2, 1, 5));
  const double z = rows / 2.0;
  s.bodies.push_back(dragged(3.0, {PathKey{0, {6.0, 0.5, z}}, PathKey{120, {cols - 7.0, 0.5, z}},
                                   PathKey{160, {cols - 7.0, -1.0, z - 8}}}));
  s.bodies.push_back(ball({cols / 4.0, 3.0, rows / 4.0}, 2.0, 30.0, {0.0, -0.3, 0.0}));
  s.bodies.push_back(ball({0.7 * cols, 2.0, 0.75 * rows}, 2.5, 20.0, {0.05, 0.0, -0.02}));
  return s;
}

// In grid units, double precision: how far the deepest non-fixed node lies inside a body, as a
// fraction of its radius (0: none inside), and how many nodes touch a body's surface.
struct Penetration {
  double deepest = 0;
  int touching = 0;
};
Penetration penetration(const WaterState& s, const WaterModel& m) {
  Penetration p;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
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
  EXPECT_NEAR(reference.state().vy[node], reference.state().bodies[0].vy + m.bodies[0].constants.gravity_dt, 1e-6);
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

// Vertical momentum in node-mass units: sum(vy) + vy_body / (m / M).
double momentum(const WaterState& s, const WaterModel& m) {
  double p = 0;
  for (std::size_t n = 0; n < s.nodes(); ++n) p += s.vy[n];
  for (std::size_t b = 0; b < m.bodies.size(); ++b)
    if (m.bodies[b].floating()) p += s.bodies[b].vy / static_cast<double>(m.bodies[b].constants.node_over_body);
  return p;
}

TEST(Bodies, TheContactTradesMomentumBetweenWaterAndBody) {
  // One contact pass on a dented state: what the nodes gain, the body loses (gravity apart).
  Scene s = test::grid_scene(21, 21, NodeKind::free);
  s.bodies.push_back(ball({10.0, -0.5, 10.0}, 3.0, 12.0, {0.0, -0.8, 0.0}));
  const WaterModel m = sim::build_model(s);
  WaterState state = sim::rest_state(m);
  for (std::size_t n = 0; n < state.nodes(); ++n) state.vy[n] = 0.01f * static_cast<float>(n % 7);
  const double before = momentum(state, m);
  sim::resolve_contacts(state, m, 0, 0, sim::horizontal_reach(state));
  const double gravity = m.bodies[0].constants.gravity_dt / static_cast<double>(m.bodies[0].constants.node_over_body);
  const double moved = std::fabs(state.bodies[0].vy - (-0.8f - m.bodies[0].constants.gravity_dt));  // as if in air
  EXPECT_GT(moved, 0.1) << "the body must have hit the water";
  EXPECT_NEAR(momentum(state, m), before - gravity, 1e-5 * std::fabs(before));

  // And over a whole run of a free membrane without damping or gravity: only the springs and the
  // contact act, and both keep the total.
  Scene run = test::grid_scene(25, 25, NodeKind::free);
  run.physics.damping = 0;
  run.physics.gravity = 0;
  run.bodies.push_back(ball({12.0, 2.5, 12.0}, 2.0, 10.0, {0.0, -0.5, 0.0}));
  const WaterModel rm = sim::build_model(run);
  CpuSolver solver(rm, Backend::scalar, 1);
  const double start = momentum(solver.state(), rm);
  solver.advance(400);
  EXPECT_GT(std::fabs(solver.state().bodies[0].vy - -0.5f), 0.1f) << "the water must have slowed the ball";
  EXPECT_NEAR(momentum(solver.state(), rm), start, 1e-4 * std::fabs(start));
}

// The vertical spring force on node n (world units: stiffness * the grid-unit sum * spacing).
double spring_force_y(const WaterState& s, const WaterModel& m, int i, int j) {
  const double ratio = m.physics.rest_ratio;
  double f = 0;
  const std::size_t a = static_cast<std::size_t>(i) * m.cols + j;
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj) {
      if ((di == 0 && dj == 0) || i + di < 0 || j + dj < 0 || i + di >= m.rows || j + dj >= m.cols) continue;
      const std::size_t b = static_cast<std::size_t>(i + di) * m.cols + (j + dj);
      const double dx = static_cast<double>(dj) + s.ux[b] - s.ux[a], dy = static_cast<double>(s.uy[b]) - s.uy[a],
                   dz = static_cast<double>(di) + s.uz[b] - s.uz[a];
      const double rest = ratio * std::sqrt(static_cast<double>(di * di + dj * dj));
      f += dy * (1 - rest / std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  return f * m.physics.stiffness * m.spacing;
}

TEST(Bodies, AFloatingBallComesToRestCarriedByTheSprings) {
  // A pre-tensioned pool (rest_ratio < 1) carries a ball: at rest the springs' vertical pull on the
  // nodes under it balances its weight plus the damping of those nodes, which the contact leaves
  // moving up at g dt each substep (gravity is taken from the body after the contact): N gamma g dt.
  // Within 0.1 %: what is left of the ball's oscillation after the run.
  Scene s = test::grid_scene(41, 41);
  s.physics.rest_ratio = 0.9;
  s.physics.damping = 0.2;
  s.physics.gravity = 0.05;
  const double mass = 40.0;
  s.bodies.push_back(ball({20.0, 2.5, 20.0}, 3.0, mass));
  const WaterModel m = sim::build_model(s);
  CpuSolver solver(m, Backend::scalar, 1);
  solver.advance(6000);
  const WaterState& st = solver.state();
  const sim::BodyState& b = st.bodies[0];
  double carried = 0;
  int nodes = 0;
  for (int i = 0; i < m.rows; ++i)
    for (int j = 0; j < m.cols; ++j) {
      const std::size_t n = static_cast<std::size_t>(i) * m.cols + j;
      const double dx = static_cast<double>(j) + st.ux[n] - b.x, dy = static_cast<double>(st.uy[n]) - b.y,
                   dz = static_cast<double>(i) + st.uz[n] - b.z;
      if (std::fabs(std::sqrt(dx * dx + dy * dy + dz * dz) - 3.0) < 1e-3 && dy < 0) {
        carried += spring_force_y(st, m, i, j);
        ++nodes;
      }
    }
  const double weight = mass * s.physics.gravity;
  const double node_drag = nodes * s.physics.damping * s.physics.gravity * s.physics.dt;
  EXPECT_GE(nodes, 4);
  EXPECT_LT(std::fabs(b.vy), 1e-3) << "at rest";
  EXPECT_LT(b.y - 3.0, -0.1) << "it sits in the water, its bottom below the rest plane";
  EXPECT_NEAR(carried, weight + node_drag, 1e-3 * weight) << nodes << " nodes carry it; centre at y = " << b.y;
  std::printf("%d nodes carry %.6g: the weight %.6g + their damping %.6g; the ball's bottom at y = %.4g\n", nodes,
              carried, weight, node_drag, b.y - 3.0);
}

TEST(Bodies, ADraggedSphereLeavesAWakeBehindAndNotAhead) {
  Scene s = test::grid_scene(33, 161);
  s.bodies.push_back(dragged(3.0, {PathKey{0, {10.0, 0.5, 16.0}}, PathKey{200, {150.0, 0.5, 16.0}}}));
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
