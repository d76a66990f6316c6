#include "tree/wind_state.h"

#include <algorithm>
#include <cmath>

namespace pond::tree {
namespace {
// The article's noise rates (samples per second), picked by eye.
constexpr double kGustRateX = 63.0, kGustRateZ = 50.0;
constexpr double kTwigRate[3] = {33.0, 52.0, 94.0};
constexpr float kTwigAmplitude = 10.0f;
constexpr double kPhaseSpan = 64.0;
constexpr int kMaxInertiaSteps = 1000;

float magnitude(WindXZ w) { return std::sqrt(w.x * w.x + w.z * w.z); }
}  // namespace

WindXZ user_wind_vector(const UserWind& user) {
  const float strength = std::clamp(user.strength, 0.0f, kMaxWindStrength);
  const float len = strength * user.units_per_strength;
  return {len * std::cos(user.direction), len * std::sin(user.direction)};
}

WindXZ gust_target(const NoiseTable& noise, WindXZ w, double t) {
  return {w.x * (1.0f - 0.5f * sample_noise(noise, t * kGustRateX)),
          w.z * (1.0f - 0.5f * sample_noise(noise, t * kGustRateZ))};
}

Vec3 twig_noise(const NoiseTable& noise, WindXZ w, double t) {
  const float amplitude = kTwigAmplitude * magnitude(w);
  return {sample_noise(noise, t * kTwigRate[0]) * amplitude,
          sample_noise(noise, t * kTwigRate[1]) * amplitude,
          sample_noise(noise, t * kTwigRate[2]) * amplitude};
}

WindXZ inertia_step(WindXZ wind, WindXZ target, float dt) {
  return {wind.x * (1.0f - dt) + target.x * dt, wind.z * (1.0f - dt) + target.z * dt};
}

void advance_wind(WindState& state, const NoiseTable& noise, const UserWind& user, double dt) {
  if (!(dt > 0.0)) return;  // also NaN
  state.time += dt;
  const WindXZ target = gust_target(noise, user_wind_vector(user), state.time + state.phase);
  const double steps = std::ceil(dt / kMaxInertiaStep);
  if (steps > kMaxInertiaSteps) {
    state.wind = target;
    return;
  }
  const int n = static_cast<int>(steps);
  const auto h = static_cast<float>(dt / n);
  for (int k = 0; k < n; ++k) state.wind = inertia_step(state.wind, target, h);
}

TreeWindFrame wind_frame(const WindState& state, const NoiseTable& noise, const UserWind& user,
                         BendMode mode) {
  const WindXZ w = user_wind_vector(user);
  const double t = state.time + state.phase;
  const Vec3 q = twig_noise(noise, w, t);
  TreeWindFrame f{};
  f.wind = {state.wind.x, 0.0f, state.wind.z, 0.0f};
  f.twig = {q.x, q.y, q.z, 0.0f};
  f.time = static_cast<float>(t);
  f.strength = magnitude(w);
  f.bend_mode = static_cast<std::uint32_t>(mode);
  return f;
}

double instance_phase(int instance) {
  constexpr double kGoldenFraction = 0.6180339887498949;
  const double k = static_cast<double>(instance) * kGoldenFraction;
  return (k - std::floor(k)) * kPhaseSpan;
}

}  // namespace pond::tree
