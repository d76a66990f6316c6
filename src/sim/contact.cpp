#include "sim/contact.h"

#include <array>

namespace pond::sim {

void resolve_contacts(WaterState& s, const WaterModel& m, std::int64_t step, int substep) {
  for (std::size_t index = 0; index < m.bodies.size(); ++index) {
    const BodyModel& model = m.bodies[index];
    const shared::BodyConstants& c = model.constants;
    BodyState& b = s.bodies[index];
    if (model.floating())
      b = shared::contact_move_floating(b, m.constants.dt, static_cast<float>(m.cols - 1),
                                        static_cast<float>(m.rows - 1));
    else
      b = kinematic_state(model, step, substep, m.substeps, m.physics.dt);

    const int i0 = shared::footprint_first(b.z, c.radius), i1 = shared::footprint_last(b.z, c.radius, m.rows - 1);
    const int j0 = shared::footprint_first(b.x, c.radius), j1 = shared::footprint_last(b.x, c.radius, m.cols - 1);
    if (i1 < i0 || j1 < j0) continue;
    const int width = j1 - j0 + 1, count = width * (i1 - i0 + 1);
    // The half chord over node k of the footprint, 0 where it is fixed or outside the sphere.
    auto half_height_at = [&](int k, std::size_t& n) {
      const int i = i0 + k / width, j = j0 + k % width;
      n = static_cast<std::size_t>(i) * m.cols + j;
      if (m.kinds[n] == static_cast<std::uint8_t>(NodeKind::fixed)) return 0.0f;
      return shared::contact_half_height(static_cast<float>(j) + s.ux[n], static_cast<float>(i) + s.uz[n], b.x,
                                         b.z, c.radius2);
    };
    float common_v = b.vy;
    if (model.floating()) {
      std::array<float, shared::kContactLanes> sums{};
      std::array<std::uint32_t, shared::kContactLanes> counts{};
      for (int k = 0; k < count; ++k) {
        std::size_t n;
        const float half = half_height_at(k, n);
        if (half > 0.0f && shared::contact_inside(s.uy[n], b.y, half)) {
          sums[k % shared::kContactLanes] = sums[k % shared::kContactLanes] + s.vy[n];
          ++counts[k % shared::kContactLanes];
        }
      }
      float sum = 0.0f;
      std::uint32_t nodes = 0;
      for (int lane = 0; lane < shared::kContactLanes; ++lane) {
        sum = sum + sums[lane];
        nodes += counts[lane];
      }
      if (nodes > 0) common_v = shared::contact_common_velocity(b.vy, sum, nodes, c.node_over_body);
      b.vy = shared::contact_fall(common_v, c.gravity_dt);
    }
    for (int k = 0; k < count; ++k) {
      std::size_t n;
      const float half = half_height_at(k, n);
      if (half > 0.0f && shared::contact_inside(s.uy[n], b.y, half)) {
        s.uy[n] = shared::contact_surface(s.uy[n], b.y, half);
        s.vy[n] = common_v;
      }
    }
  }
}

}  // namespace pond::sim
