#include "sim/diagnostics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/errors.h"

namespace pond::sim {

Diagnostics diagnose(const WaterState& s, const WaterModel& m) {
  Diagnostics d;
  const double h = m.spacing, c = m.physics.stiffness, mass = m.physics.mass;
  const double edge = m.physics.rest_ratio * h, diag = edge * std::sqrt(2.0);
  const int R = m.rows;
  const std::size_t C = static_cast<std::size_t>(m.cols);
  auto spring = [&](std::size_t a, std::size_t b, double rest) {
    const double dx = (double(s.ux[b]) - s.ux[a] + double(b % C) - double(a % C)) * h,
                 dy = (double(s.uy[b]) - s.uy[a]) * h,
                 dz = (double(s.uz[b]) - s.uz[a] + double(b / C) - double(a / C)) * h;
    const double stretch = std::sqrt(dx * dx + dy * dy + dz * dz) - rest;
    d.spring += 0.5 * c * stretch * stretch;
  };
  for (int i = 0; i < R; ++i)
    for (std::size_t j = 0; j < C; ++j) {
      const std::size_t n = static_cast<std::size_t>(i) * C + j;
      const double vx = s.vx[n] * h, vy = s.vy[n] * h, vz = s.vz[n] * h;
      d.kinetic += 0.5 * mass * (vx * vx + vy * vy + vz * vz);
      const double ux = s.ux[n] * h, uy = s.uy[n] * h, uz = s.uz[n] * h;
      d.max_displacement = std::max(d.max_displacement, std::sqrt(ux * ux + uy * uy + uz * uz));
      if (j + 1 < C) spring(n, n + 1, edge);
      if (i + 1 < R) {
        spring(n, n + C, edge);
        if (j + 1 < C) spring(n, n + C + 1, diag);
        if (j > 0) spring(n, n + C - 1, diag);
      }
    }
  return d;
}

std::uint64_t state_hash(std::span<const float> data) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  for (std::size_t i = 0; i < data.size_bytes(); ++i) {
    h ^= bytes[i];
    h *= 0x100000001b3ull;
  }
  return h;
}

std::uint64_t state_hash(const WaterState& s, const WaterModel& m) {
  const auto world = to_world_interleaved(s, m);
  return state_hash(world);
}

std::optional<std::size_t> first_blown_up_node(const WaterState& s) {
  for (std::size_t n = 0; n < s.nodes(); ++n)
    if (!std::isfinite(s.vx[n]) || !std::isfinite(s.vy[n]) || !std::isfinite(s.vz[n]) || !(std::fabs(s.vy[n]) < 1e30f))
      return n;
  return std::nullopt;
}

std::optional<std::size_t> first_blown_up_body(const WaterState& s) {
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    for (float c : {s.bodies[b].x, s.bodies[b].y, s.bodies[b].z, s.bodies[b].vx, s.bodies[b].vy, s.bodies[b].vz})
      if (!(std::fabs(c) < 1e30f)) return b;
  return std::nullopt;
}

namespace {

// "body B (floating, radius r)" in world units.
std::string body_name(const WaterModel& m, std::size_t b) {
  char text[96];
  std::snprintf(text, sizeof text, "body %zu (%s, radius %g)", b, m.bodies[b].floating() ? "floating" : "kinematic",
                static_cast<double>(m.bodies[b].constants.radius) * m.spacing);
  return text;
}

// The first body whose reach (its radius plus a spacing) covers node n, if any.
std::optional<std::size_t> body_over_node(const WaterState& s, const WaterModel& m, std::size_t n) {
  const double i = static_cast<double>(n / static_cast<std::size_t>(m.cols)), j = static_cast<double>(n % static_cast<std::size_t>(m.cols));
  for (std::size_t b = 0; b < s.bodies.size() && b < m.bodies.size(); ++b) {
    const double dx = j - s.bodies[b].x, dz = i - s.bodies[b].z, r = m.bodies[b].constants.radius + 1.0;
    if (dx * dx + dz * dz <= r * r) return b;
  }
  return std::nullopt;
}

}  // namespace

void throw_blow_up(const WaterState& state, const WaterModel& model, const std::string& prefix) {
  if (!first_blown_up_node(state))
    if (const std::optional<std::size_t> b = first_blown_up_body(state)) {
      const bool clamped = (state.bodies[*b].flags & shared::kBodyClamped) != 0u;
      throw InputError(prefix + body_name(model, *b) + " blew up (non-finite position or velocity) " +
                       (clamped ? "after its speed was clamped: it was thrown or pushed too hard; "
                                : "though the water around it is finite; ") +
                       "check its density or mass against the stable range in docs/bodies.md, or raise physics.substeps");
    }
  const std::size_t n = first_blown_up_node(state).value_or(state.nodes() - 1);
  const auto cols = static_cast<std::size_t>(model.cols);
  const std::optional<std::size_t> under = body_over_node(state, model, n);
  throw InputError(prefix + "the water blew up (non-finite velocity at node row " + std::to_string(n / cols) +
                   ", col " + std::to_string(n % cols) +
                   (under ? ", under " + body_name(model, *under) + ": its pushes were too strong for the springs"
                          : std::string()) +
                   "); lower physics.dt, raise physics.substeps or soften the perturbations");
}

}  // namespace pond::sim
