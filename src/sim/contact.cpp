#include "sim/contact.h"

#include <array>
#include <cmath>

namespace pond::sim {

void resolve_contacts(WaterState& s, const WaterModel& m, std::int64_t step, int substep, float reach) {
  for (std::size_t index = 0; index < m.bodies.size(); ++index) {
    const BodyModel& model = m.bodies[index];
    const shared::BodyConstants& c = model.constants;
    BodyState& b = s.bodies[index];
    if (model.floating())
      b = shared::contact_move_floating(b, m.constants.dt, static_cast<float>(m.cols - 1),
                                        static_cast<float>(m.rows - 1));
    else
      b = kinematic_state(model, step, substep, m.substeps, m.physics.dt);

    const float extent = shared::contact_extent(c.radius, reach), limit2 = shared::contact_touch_limit2(c.radius);
    const int i0 = shared::footprint_first(b.z, extent), i1 = shared::footprint_last(b.z, extent, m.rows - 1);
    const int j0 = shared::footprint_first(b.x, extent), j1 = shared::footprint_last(b.x, extent, m.cols - 1);
    // Calls visit(i, j, n, half chord) for every node of the footprint, row-major, that is not
    // fixed and lies inside the sphere (shared/bodies.h, step 2).
    auto for_inside = [&](auto&& visit) {
      for (int i = i0; i <= i1; ++i)
        for (int j = j0; j <= j1; ++j) {
          if (!shared::contact_may_touch(j, i, b.x, b.z, reach, limit2)) continue;
          const std::size_t n = static_cast<std::size_t>(i) * m.cols + j;
          if (m.kinds[n] == static_cast<std::uint8_t>(NodeKind::fixed)) continue;
          const float half = shared::contact_half_height(static_cast<float>(j) + s.ux[n],
                                                         static_cast<float>(i) + s.uz[n], b.x, b.z, c.radius2);
          if (half > 0.0f && shared::contact_inside(s.uy[n], b.y, half)) visit(i, j, n, half);
        }
    };
    float common_v = b.vy;
    if (model.floating()) {
      std::array<float, shared::kContactLanes> sums{};
      std::array<std::uint32_t, shared::kContactLanes> counts{};
      for_inside([&](int i, int j, std::size_t n, float) {
        const int lane = shared::contact_lane(i, j);
        sums[lane] = sums[lane] + s.vy[n];
        ++counts[lane];
      });
      float sum = 0.0f;
      std::uint32_t nodes = 0;
      for (int lane = 0; lane < shared::kContactLanes; ++lane) {
        sum = sum + sums[lane];
        nodes += counts[lane];
      }
      if (nodes > 0) common_v = shared::contact_common_velocity(b.vy, sum, nodes, c.node_over_body);
      b.vy = shared::contact_fall(common_v, c.gravity_dt);
    }
    for_inside([&](int, int, std::size_t n, float half) {
      s.uy[n] = shared::contact_surface(s.uy[n], b.y, half);
      s.vy[n] = common_v;
    });
  }
}

float horizontal_reach(const WaterState& s) {
  float reach = 0.0f;
  for (std::size_t n = 0; n < s.ux.size(); ++n) {
    const float a = std::abs(s.ux[n]), b = std::abs(s.uz[n]);
    reach = a > reach ? a : reach;
    reach = b > reach ? b : reach;
  }
  return reach;
}

}  // namespace pond::sim
