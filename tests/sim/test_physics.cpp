// The water model's physics: equilibrium, constraints, symmetry, reflection, superposition,
// damping, and perturbations landing exactly as the scene contract defines them.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstring>

#include "core/errors.h"

#include "shared/exact_math.h"
#include "sim/diagnostics.h"
#include "sim/model.h"
#include "sim/perturbation.h"
#include "test_util.h"

namespace pond::sim {
namespace {

using scene::load_scene;
using scene::parse_scene;
using scene::Scene;
using test::grid_scene;
using test::node;
using test::run;
using test::splash;

bool same_bits(const AlignedBuffer<float>& a, const AlignedBuffer<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

bool same_state(const WaterState& a, const WaterState& b) {
  return same_bits(a.ux, b.ux) && same_bits(a.uy, b.uy) && same_bits(a.uz, b.uz) && same_bits(a.vx, b.vx) &&
         same_bits(a.vy, b.vy) && same_bits(a.vz, b.vz);
}

TEST(Physics, RestStaysAtRestBitForBit) {
  for (NodeKind border : {NodeKind::fixed, NodeKind::vertical, NodeKind::free})
    for (double spacing : {1.0, 0.7, 3.0})
      for (MathMode math : {MathMode::exact, MathMode::fast}) {
        Scene s = grid_scene(13, 21, border);
        s.grid.spacing = spacing;
        const WaterModel m = build_model(s, math);
        const WaterState after = run(s, 200, Backend::scalar, 1, math);
        EXPECT_TRUE(same_state(after, rest_state(m)))
            << "border " << int(border) << " spacing " << spacing << " math " << int(math);
      }
}

TEST(Physics, CalibratedRestLengthsMakeTheRestForceExactlyZero) {
  for (int steps : {2, 3}) {
    const float edge = calibrated_rest_length(1.0f, 1.0f, steps);
    const float diag = calibrated_rest_length(std::sqrt(2.0f), 2.0f, steps);
    EXPECT_EQ(shared::spring_factor(1.0f, edge, steps), 0.0f);
    EXPECT_EQ(shared::spring_factor(2.0f, diag, steps), 0.0f);
    // The calibration moves the rest length by at most a few ulp of float.
    // The calibration absorbs the error of the approximate rsqrt at the rest length: float
    // rounding for three Newton steps, 4.7e-6 for two.
    const float tolerance = steps == 3 ? 1e-6f : 1e-5f;
    EXPECT_NEAR(edge, 1.0f, tolerance);
    EXPECT_NEAR(diag, std::sqrt(2.0f), tolerance);
  }
}

// The GPU's fast mode computes an rsqrt accurate to rounding, so its rest lengths are calibrated
// for that, not for the CPU's two-step rsqrt (whose 4.7e-6 would be tension at rest on the GPU);
// exact mode keeps the model's constants, and so its bits.
TEST(Physics, GpuFastRestLengthsLeaveNoTensionForAnAccurateRsqrt) {
  Scene s = grid_scene(9, 9, NodeKind::vertical);
  const WaterModel fast = build_model(s, MathMode::fast), exact = build_model(s, MathMode::exact);
  const auto [edge, diag] = gpu_rest_lengths(fast);
  EXPECT_EQ(1.0f - edge * 1.0f, 0.0f);
  EXPECT_EQ(1.0f - diag * static_cast<float>(1.0 / std::sqrt(2.0)), 0.0f);
  EXPECT_NE(diag, fast.constants.rest_diag);  // the CPU's fast calibration is 4.7e-6 away
  const auto [exact_edge, exact_diag] = gpu_rest_lengths(exact);
  EXPECT_EQ(exact_edge, exact.constants.rest_edge);
  EXPECT_EQ(exact_diag, exact.constants.rest_diag);
}

TEST(Physics, FixedNodesNeverMoveAndVerticalNodesKeepXZ) {
  Scene s = grid_scene(30, 30, NodeKind::vertical);
  s.constraints.push_back({NodeKind::fixed, 10, 14, 16, 20});
  s.constraints.push_back({NodeKind::vertical, 20, 25, 5, 8});
  s.perturbations.push_back(splash(12, 12, 2.0, 1.5));
  s.perturbations.push_back(splash(22, 7, 1.0, 1.0, 40, PerturbTarget::position));
  const WaterModel m = build_model(s);
  const WaterState rest = rest_state(m);
  CpuSolver solver(m, Backend::scalar, 1);
  bool moved_vertically = false;
  for (int round = 0; round < 20; ++round) {
    solver.advance(10);
    const WaterState& st = solver.state();
    for (std::size_t n = 0; n < m.nodes(); ++n) {
      const auto kind = static_cast<NodeKind>(m.kinds[n]);
      if (kind == NodeKind::free) continue;
      ASSERT_EQ(st.ux[n], rest.ux[n]) << n;
      ASSERT_EQ(st.uz[n], rest.uz[n]) << n;
      ASSERT_EQ(st.vx[n], 0.0f);
      ASSERT_EQ(st.vz[n], 0.0f);
      if (kind == NodeKind::fixed) {
        ASSERT_EQ(st.uy[n], 0.0f) << n;
        ASSERT_EQ(st.vy[n], 0.0f) << n;
      } else if (st.uy[n] != 0.0f) {
        moved_vertically = true;
      }
    }
  }
  EXPECT_TRUE(moved_vertically) << "vertical-only nodes must stay free in y";
}

TEST(Physics, FixedWinsOverVertical) {
  Scene s = grid_scene(10, 10, NodeKind::vertical);
  s.constraints.push_back({NodeKind::fixed, 0, 3, 0, 3});
  s.constraints.push_back({NodeKind::vertical, 2, 5, 2, 5});
  const WaterModel m = build_model(s);
  EXPECT_EQ(m.kinds[0], std::uint8_t(NodeKind::fixed));  // border corner inside the fixed block
  EXPECT_EQ(m.kinds[2 * 10 + 2], std::uint8_t(NodeKind::fixed));
  EXPECT_EQ(m.kinds[4 * 10 + 4], std::uint8_t(NodeKind::vertical));
  EXPECT_EQ(m.kinds[6 * 10 + 6], std::uint8_t(NodeKind::free));
  EXPECT_EQ(m.kinds[0 * 10 + 6], std::uint8_t(NodeKind::vertical));  // border
}

TEST(Physics, CentredSplashOnASquareGridStaysMirrorSymmetric) {
  Scene s = grid_scene(41, 41);
  s.perturbations.push_back(splash(20, 20, 3.0, 1.0));
  const WaterState st = run(s, 150);
  double max_y = 0, max_asym = 0;
  for (int i = 0; i < 41; ++i)
    for (int j = 0; j < 41; ++j) {
      const float y = st.uy[node(s, i, j)];
      max_y = std::max(max_y, double(std::fabs(y)));
      for (auto [a, b] : {std::pair{40 - i, j}, {i, 40 - j}, {j, i}})
        max_asym = std::max(max_asym, double(std::fabs(y - st.uy[node(s, a, b)])));
    }
  EXPECT_GT(max_y, 1e-3);
  // The summation order is not symmetric, so mirror images agree to rounding, not to the bit.
  EXPECT_LT(max_asym, 1e-5 * max_y) << "max |y| " << max_y << ", max asymmetry " << max_asym;
}

// Vertical displacement at one node over time.
std::vector<float> probe(const Scene& s, int i, int j, int steps) {
  CpuSolver solver(build_model(s), best_backend(), 1);
  std::vector<float> out;
  for (int t = 0; t < steps; ++t) {
    solver.advance(1);
    out.push_back(solver.state().uy[node(s, i, j)]);
  }
  return out;
}

// A wave reaches the probe from a reflector: the bounded run agrees with an unbounded one (a
// much larger pond, same neighbourhood) until the reflection arrives, then departs from it.
void expect_reflection(Scene near, Scene far, int probe_i, int probe_j, int offset_i, int offset_j) {
  const int steps = 150;
  const auto a = probe(near, probe_i, probe_j, steps);
  const auto b = probe(far, probe_i + offset_i, probe_j + offset_j, steps);
  int first_difference = -1;
  double late_difference = 0, peak = 0;
  for (int t = 0; t < steps; ++t) {
    peak = std::max(peak, double(std::fabs(b[t])));
    if (a[t] != b[t] && first_difference < 0) first_difference = t;
    if (first_difference >= 0) late_difference = std::max(late_difference, double(std::fabs(a[t] - b[t])));
  }
  ASSERT_GE(first_difference, 5) << "the reflector must not act at a distance";
  EXPECT_GT(late_difference, 0.1 * peak) << "the reflected wave must be strong, peak " << peak;
}

TEST(Physics, WavesReflectFromAFixedShore) {
  Scene near = grid_scene(40, 40);
  near.perturbations.push_back(splash(20, 12, 1.5, 1.0));
  Scene far = grid_scene(120, 120);
  far.perturbations.push_back(splash(60, 52, 1.5, 1.0));
  expect_reflection(near, far, 20, 8, 40, 40);  // the probe lies between the splash and the shore
}

TEST(Physics, WavesReflectFromAnIsland) {
  Scene island = grid_scene(60, 60);
  island.constraints.push_back({NodeKind::fixed, 27, 33, 36, 42});
  island.perturbations.push_back(splash(30, 24, 1.5, 1.0));
  Scene open = island;
  open.constraints.clear();
  expect_reflection(island, open, 30, 30, 0, 0);
}

TEST(Physics, SmallWavesSuperposeAndPassThroughEachOther) {
  // With pre-tensioned springs the small-amplitude model is linear: the two-splash run equals the
  // sum of the single-splash runs, also after the wave fronts crossed.
  auto scene = [](bool a, bool b) {
    Scene s = grid_scene(40, 60);
    s.physics.rest_ratio = 0.8;
    if (a) s.perturbations.push_back(splash(20, 15, 2.0, 0.01));
    if (b) s.perturbations.push_back(splash(20, 45, 2.0, -0.01));
    return s;
  };
  const int steps = 150;  // the fronts meet near step 45 (about a third of a node per step)
  const WaterState ab = run(scene(true, true), steps), a = run(scene(true, false), steps),
                   b = run(scene(false, true), steps);
  double worst = 0, peak = 0;
  for (std::size_t n = 0; n < ab.nodes(); ++n) {
    worst = std::max(worst, double(std::fabs(ab.uy[n] - (a.uy[n] + b.uy[n]))));
    peak = std::max(peak, double(std::fabs(ab.uy[n])));
  }
  EXPECT_GT(peak, 1e-3);
  EXPECT_LT(worst, 2e-3 * peak);
  // Each wave went through the other: A's wave is past B's starting point.
  EXPECT_GT(std::fabs(a.uy[test::node(scene(true, false), 20, 52)]), 1e-3 * peak);
}

TEST(Physics, DampingMakesTheEnergyDecayAndNoDampingKeepsIt) {
  for (double damping : {0.0, 0.05, 0.5}) {
    Scene s = grid_scene(30, 30);
    s.physics.damping = damping;
    s.perturbations.push_back(splash(15, 15, 2.0, 0.5));
    const WaterModel m = build_model(s);
    CpuSolver solver(m, Backend::scalar, 1);
    solver.advance(5);
    const double e0 = diagnose(solver.state(), m).total();
    solver.advance(400);
    const double e1 = diagnose(solver.state(), m).total();
    if (damping == 0.0) {
      EXPECT_NEAR(e1, e0, 0.05 * e0) << "semi-implicit Euler keeps energy bounded";
    } else {
      EXPECT_LT(e1, e0 * (damping >= 0.5 ? 0.01 : 0.6)) << "damping " << damping;
    }
  }
}

TEST(Physics, PerturbationTableMatchesTheContract) {
  Scene s = grid_scene(30, 40);
  s.grid.spacing = 0.5;
  s.constraints.push_back({NodeKind::fixed, 10, 11, 10, 11});
  const Perturbation p = splash(10.3, 12.6, 1.25, -0.8);
  const WaterModel m = build_model(s);
  const PerturbationTable t = tabulate(p, m);
  std::size_t k = 0;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 40; ++j) {
      const double d = std::hypot((i - p.row) * 0.5, (j - p.col) * 0.5);
      const bool fixed = m.kinds[node(s, i, j)] == std::uint8_t(NodeKind::fixed);
      if (d > 3 * p.radius || fixed) continue;
      ASSERT_LT(k, t.nodes.size());
      ASSERT_EQ(t.nodes[k], node(s, i, j));
      const double w = p.amplitude * std::exp(-d * d / (2 * p.radius * p.radius));
      EXPECT_NEAR(t.weights[k] * 0.5, w, 1e-7) << i << "," << j;  // table is in grid units
      ++k;
    }
  EXPECT_EQ(k, t.nodes.size());
}

TEST(Physics, PerturbationLandsJustBeforeItsStep) {
  for (auto target : {PerturbTarget::velocity, PerturbTarget::position})
    for (auto mode : {PerturbMode::add, PerturbMode::set}) {
      Scene s = grid_scene(20, 20);
      s.perturbations.push_back(splash(8, 8, 1.0, 0.7, 0, target, mode));  // a first disturbance
      s.perturbations.push_back(splash(10, 10, 1.5, 0.5, 7, target, mode));
      Scene without = s;
      without.perturbations.pop_back();
      const WaterModel m = build_model(s);
      CpuSolver a(m, Backend::scalar, 1), b(build_model(without), Backend::scalar, 1);
      a.advance(7);
      b.advance(7);
      ASSERT_TRUE(same_state(a.state(), b.state())) << "nothing before step 7";
      // Step 7 = the perturbation on the state after 7 steps, then one integration.
      WaterState expected = b.state();
      apply_perturbation(m.perturbations.back(), expected);
      const std::size_t centre = node(s, 10, 10);
      const float before = (target == PerturbTarget::velocity ? b.state().vy : b.state().uy)[centre];
      const float w = m.perturbations.back().weights[std::find(m.perturbations.back().nodes.begin(),
                                                               m.perturbations.back().nodes.end(),
                                                               centre) -
                                                     m.perturbations.back().nodes.begin()];
      EXPECT_FLOAT_EQ(w, 0.5f);  // the centre's weight is the amplitude
      const float after = (target == PerturbTarget::velocity ? expected.vy : expected.uy)[centre];
      EXPECT_EQ(after, mode == PerturbMode::add ? before + w : w);
      // Continuing from that state without the perturbation in the schedule equals the real run.
      CpuSolver d(build_model(without), Backend::scalar, 1);
      d.set_state(expected, 7);
      d.advance(1);
      a.advance(1);
      EXPECT_TRUE(same_state(a.state(), d.state()));
    }
}

TEST(Physics, LargeSplashGivesAMultiValuedProfile) {
  // The "underwater explosion": a strong upward splash throws nodes sideways far enough that the
  // surface folds over: x = j + ux along some row stops increasing with the column index.
  Scene s = grid_scene(41, 41);
  s.perturbations.push_back(splash(20, 20, 2.0, 12.0));
  CpuSolver solver(build_model(s), Backend::scalar, 1);
  bool folded = false;
  for (int t = 0; t < 60 && !folded; ++t) {
    solver.advance(1);
    const WaterState& st = solver.state();
    for (int i = 0; i < 41 && !folded; ++i)
      for (int j = 1; j < 41; ++j)
        if (st.ux[node(s, i, j)] - st.ux[node(s, i, j - 1)] <= -1.0f) folded = true;
  }
  EXPECT_TRUE(folded);
}

TEST(Physics, BlowUpStopsWithTheStepNamed) {
  Scene s = grid_scene(20, 20);
  s.physics.dt = 0.8;  // beyond the bound 0.532; build_model does not check, the parser does
  s.perturbations.push_back(splash(10, 10, 1.0, 0.1));
  CpuSolver solver(build_model(s), Backend::scalar, 1);
  try {
    solver.advance(100000);
    FAIL() << "an unstable run must stop";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("step "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("blew up"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pond::sim
