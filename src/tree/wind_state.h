#pragma once
// The wind over time (SPEC section 2): the user's wind W, gusts drawn from the noise, the article's
// inertia, the twig noise q, and the per-frame uniforms the vertex shader receives. Plain data plus
// free functions; one WindState per tree instance, so that instances with different phases sway
// out of step under the same user wind.
#include <cstdint>

#include "tree/bend_mode.h"
#include "tree/noise.h"
#include "tree/vec3.h"

namespace pond::tree {

using TreeWindFrame = shared::tree_wind::TreeWindFrame;

inline constexpr float kMaxWindStrength = 9.0f;
// The article leaves the unit of its strengths 1..9 open. At unit wind the twig tips of a depth-8
// tree (3.5 trunk lengths tall) move up to 8.4 trunk lengths: the stiffness factors 0.3 + D - level
// sum up along each chain. So one strength step is 0.05 of a unit: strength 1 is a breeze (tips move
// 0.4), 9 a gale that bends the crown by about the tree's height.
inline constexpr float kWindPerStrength = 0.05f;
// Inertia steps are at most this long (seconds): see advance_wind.
inline constexpr double kMaxInertiaStep = 0.1;

struct WindXZ {
  float x = 0.0f, z = 0.0f;
};

struct UserWind {
  float strength = 3.0f;   // 0 (calm) .. 9: the demo's keys 1-9
  float direction = 0.0f;  // radians in the xz plane, from +x toward +z: the demo's right drag
  float units_per_strength = kWindPerStrength;
};

// W = strength * units_per_strength * (cos direction, sin direction); strength clamped to 0..9.
WindXZ user_wind_vector(const UserWind& user);

// The gusty target: (W.x * (1 - 0.5 noise(t*63)), W.z * (1 - 0.5 noise(t*50))). The two rates differ,
// so gusts change the wind's direction as well as its strength.
WindXZ gust_target(const NoiseTable& noise, WindXZ w, double t);

// The twig noise q = (noise(t*33), noise(t*52), noise(t*94)) * 10 * |W|.
Vec3 twig_noise(const NoiseTable& noise, WindXZ w, double t);

// One step of the article's inertia: wind * (1 - dt) + target * dt, for 0 <= dt <= 1.
WindXZ inertia_step(WindXZ wind, WindXZ target, float dt);

struct WindState {
  double time = 0.0;   // seconds of wind time since the start
  double phase = 0.0;  // this instance's time offset (instance_phase), added wherever time is read
  WindXZ wind{};       // the inertial wind the shader bends with; starts calm as in the article
};

// Advances time by dt seconds and moves the wind toward the gust target at the new time. The article
// applies wind*(1-dt) + target*dt once per frame, which overshoots the target when dt > 1 and
// oscillates when dt > 2 (a stalled window, a breakpoint). So a frame is split into equal inertia
// steps of at most kMaxInertiaStep (each the article's formula, against the frame's target): at
// 60 fps that is exactly the article, and a long frame converges monotonically toward the target,
// like several short frames would. Negative or NaN dt counts as 0; beyond 100 s the wind simply
// arrives at the target ((1 - 0.1)^1000 is below float resolution).
void advance_wind(WindState& state, const NoiseTable& noise, const UserWind& user, double dt);

// The per-frame uniforms for the shader and the CPU bend: the state's wind, q and time at
// state.time + state.phase.
TreeWindFrame wind_frame(const WindState& state, const NoiseTable& noise, const UserWind& user,
                         BendMode mode);

// Time offsets for tree instances so that several trees do not sway in unison: instance 0 gets 0
// (a lone tree keeps the article's timing), instance k the fractional part of k * golden ratio times
// 64 s, a low-discrepancy spread over about ten periods of the slowest noise rate (256 / 33 s).
double instance_phase(int instance);

}  // namespace pond::tree
