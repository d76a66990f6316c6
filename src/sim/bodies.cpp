#include "sim/bodies.h"

namespace pond::sim {

std::vector<BodyModel> build_bodies(const std::vector<BodySpec>& bodies, const Physics& physics,
                                    double h) {
  const double sub_dt = physics.dt / physics.substeps;
  std::vector<BodyModel> out;
  for (const BodySpec& b : bodies) {
    BodyModel m;
    const double r = b.radius / h;
    m.constants.radius = static_cast<float>(r);
    m.constants.radius2 = static_cast<float>(r * r);
    m.constants.floating = b.motion == BodyMotion::floating ? 1u : 0u;
    if (m.floating()) {
      m.constants.node_over_body = static_cast<float>(physics.mass / b.mass);
      m.constants.gravity_dt = static_cast<float>(physics.gravity * sub_dt / h);
      m.initial = {static_cast<float>(b.position[0] / h), static_cast<float>(b.position[1] / h),
                   static_cast<float>(b.position[2] / h), static_cast<float>(b.velocity[0] / h),
                   static_cast<float>(b.velocity[1] / h), static_cast<float>(b.velocity[2] / h)};
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
          static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

std::vector<float> bodies_to_world(const std::vector<BodyState>& bodies, float h) {
  std::vector<float> out;
  for (const BodyState& b : bodies)
    for (float c : {b.x, b.y, b.z, b.vx, b.vy, b.vz}) out.push_back(c * h);
  return out;
}

}  // namespace pond::sim
