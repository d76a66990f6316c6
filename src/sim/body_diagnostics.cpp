#include "sim/body_diagnostics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "sim/bodies.h"

namespace pond::sim {
namespace {

// The water level under body b (world y): the tent kernel's weighted mean height of the nodes that
// are not fixed (shared/body_water.h, in double); NaN where there is no water under it.
double water_level(const WaterState& s, const WaterModel& m, std::size_t b) {
  const BodyState& body = s.bodies[b];
  const double r = m.bodies[b].constants.radius;
  double sw = 0.0, sy = 0.0;
  for (int i = std::max(0, static_cast<int>(std::ceil(body.z - r))); i <= std::min(m.rows - 1, static_cast<int>(std::floor(body.z + r))); ++i)
    for (int j = std::max(0, static_cast<int>(std::ceil(body.x - r))); j <= std::min(m.cols - 1, static_cast<int>(std::floor(body.x + r))); ++j) {
      const std::size_t n = static_cast<std::size_t>(i) * m.cols + j;
      const double w = std::max(0.0, 1.0 - std::abs(static_cast<double>(j) - body.x) / r) * std::max(0.0, 1.0 - std::abs(static_cast<double>(i) - body.z) / r);
      if (w <= 0.0 || m.kinds[n] == static_cast<std::uint8_t>(NodeKind::fixed)) continue;
      sw += w;
      sy += w * s.uy[n];
    }
  return sw > 0.0 ? sy / sw * m.spacing : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

double body_energy(const WaterState& s, const WaterModel& m) {
  const double h = m.spacing, g = m.physics.gravity, rho = m.physics.water_density, pi = std::numbers::pi;
  double e = 0.0;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (!m.bodies[b].floating()) continue;
    const BodyState& body = s.bodies[b];
    const double mass = m.physics.mass / m.bodies[b].constants.node_over_body;
    const double vx = body.vx * h, vy = body.vy * h, vz = body.vz * h, y = body.y * h;
    e += 0.5 * mass * (vx * vx + vy * vy + vz * vz) + mass * g * y;
    const double level = water_level(s, m, b);
    if (std::isnan(level)) continue;
    const double r = m.bodies[b].constants.radius * h, hs = level - y + r;
    // integral of V_sub(h) dh from 0 to hs: pi (r h^3 - h^4 / 4) / 3 up to 2r, then V linearly.
    const double capped = std::clamp(hs, 0.0, 2.0 * r);
    double integral = pi * (r * capped * capped * capped - capped * capped * capped * capped / 4.0) / 3.0;
    if (hs > 2.0 * r) integral += 4.0 / 3.0 * pi * r * r * r * (hs - 2.0 * r);
    e += rho * g * integral;
  }
  return e;
}

}  // namespace pond::sim
