// The semi-implicit Euler stability bound: its formula, and that it is where the model really turns
// unstable (just below: bounded; just above: the fastest mode grows).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/errors.h"
#include "sim/stability.h"
#include "test_util.h"

namespace pond::sim {
namespace {

using scene::load_scene;
using scene::parse_scene;
using scene::Scene;

TEST(Stability, BoundFormula) {
  EXPECT_NEAR(stability_bound(4, 7, 0), 2 / std::sqrt(8 * 7 / 4.0), 1e-12);
  const double b = 0.05 / 4, w2 = 14;
  EXPECT_NEAR(stability_bound(4, 7, 0.05), (std::sqrt(b * b + 4 * w2) - b) / w2, 1e-12);
  EXPECT_NEAR(stability_bound(4, 7, 0.05), 0.53363, 1e-5);  // Table 1's dt = 0.4 is inside
}

// Runs a grid from rest with small random horizontal and vertical jitter (which excites every mode,
// the fastest included) and reports whether it stayed bounded.
bool stays_bounded(double dt) {
  Scene s = test::grid_scene(24, 24);
  s.physics.damping = 0.0;
  s.physics.dt = dt;
  const WaterModel m = build_model(s);
  WaterState st = rest_state(m);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> jitter(-1e-3f, 1e-3f);
  for (std::size_t n = 0; n < m.nodes(); ++n)
    if (m.kinds[n] == 0) {
      st.ux[n] = jitter(rng);
      st.uy[n] = jitter(rng);
      st.uz[n] = jitter(rng);
    }
  CpuSolver solver(m, Backend::scalar, 1);
  solver.set_state(st, 0);
  try {
    solver.advance(4000);
  } catch (const InputError&) {
    return false;
  }
  for (std::size_t n = 0; n < m.nodes(); ++n)
    if (std::fabs(solver.state().ux[n]) > 0.5f) return false;
  return true;
}

TEST(Stability, BoundIsWhereTheGridTurnsUnstable) {
  const double bound = stability_bound(4, 7, 0);
  EXPECT_TRUE(stays_bounded(0.97 * bound));
  EXPECT_FALSE(stays_bounded(1.03 * bound));
}

}  // namespace
}  // namespace pond::sim
