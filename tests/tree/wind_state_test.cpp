// The wind over time: user wind, gusts, inertia (with its long-frame clamp), twig noise, phases.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tree/wind_state.h"

namespace pond::tree {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

TEST(tree_wind_state, UserWindFromStrengthAndDirection) {
  const WindXZ w = user_wind_vector({9.0f, kPi / 2, kWindPerStrength});
  EXPECT_NEAR(w.x, 0.0f, 1e-6f);
  EXPECT_NEAR(w.z, 9 * kWindPerStrength, 1e-6f);
  const WindXZ clamped = user_wind_vector({25.0f, 0.0f, kWindPerStrength});
  EXPECT_FLOAT_EQ(clamped.x, 9 * kWindPerStrength) << "strength is clamped to 9";
  EXPECT_EQ(user_wind_vector({0.0f, 1.0f, kWindPerStrength}).x, 0.0f);
}

TEST(tree_wind_state, GustTargetFollowsTheNoiseAtItsTwoRates) {
  const NoiseTable noise = make_noise_table(4);
  const WindXZ w{0.3f, -0.2f};
  const double t = 1.234;
  const WindXZ g = gust_target(noise, w, t);
  EXPECT_FLOAT_EQ(g.x, w.x * (1.0f - 0.5f * sample_noise(noise, t * 63.0)));
  EXPECT_FLOAT_EQ(g.z, w.z * (1.0f - 0.5f * sample_noise(noise, t * 50.0)));
  // |noise| < 2, so the gusts never reverse the wind: target in W * (0, 2).
  for (double s = 0; s < 10; s += 0.01) {
    const WindXZ k = gust_target(noise, w, s);
    EXPECT_GT(k.x / w.x, 0.0f);
    EXPECT_LT(k.x / w.x, 2.0f);
  }
}

TEST(tree_wind_state, TwigNoiseScalesWithWindStrengthAndIsZeroInCalm) {
  const NoiseTable noise = make_noise_table(4);
  const Vec3 q1 = twig_noise(noise, {0.3f, 0.4f}, 2.0);  // |W| = 0.5
  EXPECT_FLOAT_EQ(q1.x, sample_noise(noise, 2.0 * 33) * 10 * 0.5f);
  EXPECT_FLOAT_EQ(q1.y, sample_noise(noise, 2.0 * 52) * 10 * 0.5f);
  EXPECT_FLOAT_EQ(q1.z, sample_noise(noise, 2.0 * 94) * 10 * 0.5f);
  EXPECT_EQ(twig_noise(noise, {0, 0}, 2.0), (Vec3{}));
}

TEST(tree_wind_state, InertiaConvergesToASteadyTargetWithoutOvershoot) {
  const NoiseTable calm{};  // all-zero noise: the target is W itself
  const UserWind user{6.0f, 0.0f, kWindPerStrength};
  const float target = user_wind_vector(user).x;
  WindState s;
  float previous = 0.0f;
  for (int frame = 0; frame < 600; ++frame) {  // 10 s at 60 fps
    advance_wind(s, calm, user, 1.0 / 60.0);
    EXPECT_GE(s.wind.x, previous) << "monotone approach, frame " << frame;
    EXPECT_LE(s.wind.x, target) << "no overshoot, frame " << frame;
    previous = s.wind.x;
  }
  EXPECT_NEAR(s.wind.x, target, 1e-4f * target) << "(1 - 1/60)^600 = 4e-5";
  EXPECT_NEAR(s.time, 10.0, 1e-9);
  // One second from calm: about 1 - e^-1 of the way, at any frame rate.
  for (double fps : {10.0, 30.0, 60.0, 144.0}) {
    WindState r;
    for (int k = 0; k < static_cast<int>(fps); ++k) advance_wind(r, calm, user, 1.0 / fps);
    EXPECT_NEAR(r.wind.x / target, 1.0 - std::exp(-1.0), 0.05) << fps << " fps";
  }
}

TEST(tree_wind_state, LongFrameIsSplitAndCannotOvershoot) {
  const NoiseTable calm{};
  const UserWind user{9.0f, 0.0f, kWindPerStrength};
  const float target = user_wind_vector(user).x;
  // The article's formula applied once with dt = 3 would give 3 * target (and -2 * the old wind).
  EXPECT_FLOAT_EQ(inertia_step({0, 0}, {target, 0}, 3.0f).x, 3.0f * target);
  WindState s;
  advance_wind(s, calm, user, 3.0);
  EXPECT_GT(s.wind.x, 0.9f * target);
  EXPECT_LE(s.wind.x, target);
  WindState forever;
  advance_wind(forever, calm, user, 1e6);
  EXPECT_EQ(forever.wind.x, target);
  // Time never runs backwards, and NaN is ignored.
  WindState frozen = s;
  advance_wind(frozen, calm, user, -1.0);
  advance_wind(frozen, calm, user, std::nan(""));
  EXPECT_EQ(frozen.time, s.time);
  EXPECT_EQ(frozen.wind.x, s.wind.x);
}

TEST(tree_wind_state, FrameCarriesWindTwigNoiseTimeAndMode) {
  const NoiseTable noise = make_noise_table(8);
  const UserWind user{4.0f, 0.3f, kWindPerStrength};
  WindState s;
  s.phase = 5.0;
  for (int k = 0; k < 30; ++k) advance_wind(s, noise, user, 1.0 / 30.0);
  const TreeWindFrame f = wind_frame(s, noise, user, BendMode::keep_length);
  EXPECT_EQ(f.wind.x, s.wind.x);
  EXPECT_EQ(f.wind.y, 0.0f);
  EXPECT_EQ(f.wind.z, s.wind.z);
  const Vec3 q = twig_noise(noise, user_wind_vector(user), s.time + s.phase);
  EXPECT_EQ(f.twig.x, q.x);
  EXPECT_EQ(f.twig.z, q.z);
  EXPECT_FLOAT_EQ(f.time, 6.0f);
  EXPECT_FLOAT_EQ(f.strength, 4.0f * kWindPerStrength);
  EXPECT_EQ(f.bend_mode, shared::tree_wind::kTreeBendKeepLength);
}

TEST(tree_wind_state, InstancePhasesAreDistinctSoTreesSwayOutOfStep) {
  EXPECT_EQ(instance_phase(0), 0.0);
  for (int a = 0; a < 16; ++a) {
    EXPECT_GE(instance_phase(a), 0.0);
    EXPECT_LT(instance_phase(a), 64.0);
    for (int b = a + 1; b < 16; ++b) EXPECT_GT(std::abs(instance_phase(a) - instance_phase(b)), 1.0);
  }
  // Two instances under the same user wind for the same time end with different winds.
  const NoiseTable noise = make_noise_table(1);
  const UserWind user{5.0f, 0.7f, kWindPerStrength};
  WindState a, b;
  b.phase = instance_phase(1);
  for (int k = 0; k < 120; ++k) {
    advance_wind(a, noise, user, 1.0 / 60.0);
    advance_wind(b, noise, user, 1.0 / 60.0);
  }
  EXPECT_NE(a.wind.x, b.wind.x);
  EXPECT_NE(wind_frame(a, noise, user, BendMode::article).twig.x,
            wind_frame(b, noise, user, BendMode::article).twig.x);
}

}  // namespace
}  // namespace pond::tree
