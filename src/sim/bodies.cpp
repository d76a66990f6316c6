#include "sim/bodies.h"

#include <numbers>
#include <string>

#include "core/errors.h"

namespace pond::sim {

double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

double body_density(const BodySpec& b, const Physics& p) {
  return b.density > 0.0 ? b.density : b.mass / (p.water_density * sphere_volume(b.radius));
}

double body_mass(const BodySpec& b, const Physics& p) {
  return b.density > 0.0 ? b.density * p.water_density * sphere_volume(b.radius) : b.mass;
}

std::vector<BodyModel> build_bodies(const std::vector<BodySpec>& bodies, const Physics& physics,
                                    double h) {
  // The contact pass holds the bodies in fixed arrays (shared memory on the GPU); a scene is
  // checked at load, so more is a caller's bug.
  if (bodies.size() > static_cast<std::size_t>(shared::kMaxBodies))
    throw InternalError("build_bodies: " + std::to_string(bodies.size()) + " bodies, at most " +
                        std::to_string(shared::kMaxBodies));
  const double sub_dt = physics.dt / physics.substeps;
  std::vector<BodyModel> out;
  for (const BodySpec& b : bodies) {
    BodyModel m;
    shared::BodyConstants& c = m.constants;
    const double r = b.radius / h;
    c.radius = static_cast<float>(r);
    c.radius2 = static_cast<float>(r * r);
    c.inv_radius = static_cast<float>(1.0 / r);
    c.inv_4r3 = static_cast<float>(1.0 / (4.0 * r * r * r));
    c.floating = b.motion == BodyMotion::floating ? 1u : 0u;
    if (m.floating()) {
      const double mass = body_mass(b, physics), density = body_density(b, physics);
      const double gravity_dt = physics.gravity * sub_dt / h;
      c.node_over_body = static_cast<float>(physics.mass / mass);
      c.body_over_node = static_cast<float>(mass / physics.mass);
      c.inv_mass = static_cast<float>(1.0 / mass);
      c.gravity_dt = static_cast<float>(gravity_dt);
      c.buoyancy_dt = static_cast<float>(gravity_dt / density);
      // rho_w C A / M with A = pi r^2 and M = density rho_w 4/3 pi r^3, in grid units (C / h).
      c.drag_dt = static_cast<float>(physics.body_drag / h * 3.0 / (4.0 * density * r) * sub_dt);
      m.initial = {static_cast<float>(b.position[0] / h), static_cast<float>(b.position[1] / h),
                   static_cast<float>(b.position[2] / h), static_cast<float>(b.velocity[0] / h),
                   static_cast<float>(b.velocity[1] / h), static_cast<float>(b.velocity[2] / h), 0u};
    } else {
      for (const PathKey& k : b.path)
        m.path.push_back({static_cast<double>(k.step), k.position[0] / h, k.position[1] / h,
                          k.position[2] / h});
      m.initial = kinematic_state(m, 0, -1, 1, physics.dt);  // at time 0
    }
    out.push_back(std::move(m));
  }
  return out;
}

BodyState kinematic_state(const BodyModel& body, std::int64_t step, int substep, int substeps,
                          double step_dt) {
  const auto& path = body.path;
  if (path.empty()) return body.initial;
  const double t = static_cast<double>(step) + static_cast<double>(substep + 1) / substeps;
  std::array<double, 3> p{path.front()[1], path.front()[2], path.front()[3]}, v{};
  if (t >= path.back()[0]) {
    p = {path.back()[1], path.back()[2], path.back()[3]};
  } else if (t > path.front()[0]) {
    std::size_t s = 1;
    while (path[s][0] < t) ++s;  // path[s - 1][0] < t <= path[s][0]
    const auto &a = path[s - 1], &b = path[s];
    const double f = (t - a[0]) / (b[0] - a[0]);
    for (int c = 0; c < 3; ++c) {
      p[c] = a[c + 1] + (b[c + 1] - a[c + 1]) * f;
      v[c] = (b[c + 1] - a[c + 1]) / ((b[0] - a[0]) * step_dt);
    }
  }
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]),
          static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 0u};
}

std::vector<float> bodies_to_world(const std::vector<BodyState>& bodies, float h) {
  std::vector<float> out;
  for (const BodyState& b : bodies)
    for (float c : {b.x, b.y, b.z, b.vx, b.vy, b.vz}) out.push_back(c * h);
  return out;
}

}  // namespace pond::sim
