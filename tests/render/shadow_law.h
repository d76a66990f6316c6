#pragma once
// Where the sun's shadows fall, from geometry alone (for the shadow tests): the step along the
// ground from a point to its shadow, and the surface point through which the eye sees a point of
// the pool floor (refraction at calm water).
#include <array>
#include <cmath>

namespace pond::test {

// The horizontal step along the ground, per unit of height, from a point to its shadow.
inline std::array<double, 2> shadow_step(const std::array<double, 3>& sun) { return {-sun[0] / sun[1], -sun[2] / sun[1]}; }

// Where, on calm water, the eye sees the floor point (fx, -depth, fz): the surface point whose view
// ray refracts (air to water, 1.33) onto it, found by bisection along the line between the eye's
// foot and the floor point.
inline std::array<double, 2> surface_point_seeing(const std::array<double, 3>& eye, double fx, double fz, double depth) {
  const double dx = fx - eye[0], dz = fz - eye[2], run = std::hypot(dx, dz), h = eye[1];
  double lo = 0, hi = run;  // the surface point's distance from the eye's foot
  for (int k = 0; k < 60; ++k) {
    const double r = 0.5 * (lo + hi), rest = run - r;
    const double sin_air = r / std::hypot(r, h), sin_water = rest / std::hypot(rest, depth);
    (sin_air > 1.33 * sin_water ? hi : lo) = r;
  }
  const double f = run > 0 ? lo / run : 0;
  return {eye[0] + dx * f, eye[2] + dz * f};
}

}  // namespace pond::test
