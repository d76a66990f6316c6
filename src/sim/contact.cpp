#include "sim/contact.h"

#include <array>
#include <cmath>

#include "shared/body_kinematic.h"
#include "shared/body_motion.h"
#include "shared/body_pairs.h"
#include "shared/body_water.h"

namespace pond::sim {
namespace {

using shared::BodyConstants;
using shared::ContactPush;
using shared::WaterMoments;

constexpr auto kFixed = static_cast<std::uint8_t>(NodeKind::fixed);
constexpr auto kFree = static_cast<std::uint8_t>(NodeKind::free);

// Step 1 for floating body b: the water under it, reduced lane by lane, then the exchange.
void exchange_with_water(WaterState& s, const WaterModel& m, BodyState& b, const BodyConstants& c) {
  const int i0 = shared::water_first(b.z, c.radius, m.rows - 1), i1 = shared::water_last(b.z, c.radius, m.rows - 1);
  const int j0 = shared::water_first(b.x, c.radius, m.cols - 1), j1 = shared::water_last(b.x, c.radius, m.cols - 1);
  // Calls visit(n, w, kind) for every water node of the kernel, row-major.
  auto for_kernel = [&](auto&& visit) {
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        const float w = shared::water_weight(j, i, b.x, b.z, c.inv_radius);
        if (!(w > 0.0f)) continue;
        const std::size_t n = static_cast<std::size_t>(i) * m.cols + j;
        if (m.kinds[n] == kFixed) continue;
        visit(i, j, n, w, m.kinds[n]);
      }
  };
  std::array<WaterMoments, shared::kContactLanes> lanes;
  lanes.fill(shared::moments_zero());
  for_kernel([&](int i, int j, std::size_t n, float w, std::uint8_t kind) {
    WaterMoments& lane = lanes[shared::contact_lane(i, j)];
    lane = shared::moments_add_node(lane, w, j, i, b.x, b.z, s.uy[n], s.vx[n], s.vy[n], s.vz[n], kind == kFree);
  });
  WaterMoments total = shared::moments_zero();
  for (const WaterMoments& lane : lanes) total = shared::moments_add(total, lane);
  const shared::WaterExchange e = shared::water_exchange(total, b, c);
  b = e.body;
  if (e.wet == 0u) return;
  for_kernel([&](int, int, std::size_t n, float w, std::uint8_t kind) {
    s.vy[n] = shared::water_kick(s.vy[n], e.cy, w);
    if (kind != kFree) return;
    s.vx[n] = shared::water_kick(s.vx[n], e.cx, w);
    s.vz[n] = shared::water_kick(s.vz[n], e.cz, w);
  });
}

// Step 2: every body through the substep, in sub-iterations (shared/body_motion.h).
void move_bodies(BodyState* sb, const BodyConstants* sc, const BodyState* sk, std::uint32_t count,
                 const std::uint32_t* land, const ContactPush& p) {
  float most = 0.0f;
  for (std::uint32_t i = 0; i < count; ++i) {
    const float move = shared::body_prepare(sb[i], sc[i], sk[i], p.max_speed, p.dt);
    most = move > most ? move : most;
  }
  const int n = shared::motion_iterations(most);
  const float dt_n = p.dt * shared::inv_exact(static_cast<float>(n));
  for (int it = 0; it < n; ++it) {
    for (std::uint32_t i = 0; i < count; ++i) sb[i] = shared::body_advance(sb[i], sc[i], sk[i], dt_n, n - it);
    for (int pass = 0; pass < POND_PAIR_PASSES; ++pass) {
      const bool pairs = shared::collide_pairs(sb, sc, count, p.bounce_speed);
      for (std::uint32_t i = 0; i < count; ++i)
        if (sc[i].floating != 0u) shared::collide_land(land, sb[i], sc[i], p);
      if (!pairs) break;
    }
  }
}

// Step 3 for kinematic body b: the nodes inside it to its surface, with its vertical velocity.
// Returns the rectangle of nodes it may have moved (empty: row0 > row1 or col0 > col1).
NodeRect push_out(WaterState& s, const WaterModel& m, const BodyState& b, const BodyConstants& c, float reach) {
  const float extent = shared::contact_extent(c.radius, reach), limit2 = shared::contact_touch_limit2(c.radius);
  const int i0 = shared::footprint_first(b.z, extent), i1 = shared::footprint_last(b.z, extent, m.rows - 1);
  const int j0 = shared::footprint_first(b.x, extent), j1 = shared::footprint_last(b.x, extent, m.cols - 1);
  for (int i = i0; i <= i1; ++i)
    for (int j = j0; j <= j1; ++j) {
      if (!shared::contact_may_touch(j, i, b.x, b.z, reach, limit2)) continue;
      const std::size_t n = static_cast<std::size_t>(i) * m.cols + j;
      if (m.kinds[n] == kFixed) continue;
      const float half = shared::contact_half_height(static_cast<float>(j) + s.ux[n], static_cast<float>(i) + s.uz[n],
                                                     b.x, b.z, c.radius2);
      if (!(half > 0.0f && shared::contact_inside(s.uy[n], b.y, half))) continue;
      s.uy[n] = shared::contact_surface(s.uy[n], b.y, half);
      s.vy[n] = b.vy;
    }
  return {i0, i1, j0, j1};
}

}  // namespace

ContactPush contact_push(const WaterModel& m) {
  const double h = m.spacing, sub_dt = m.physics.dt / m.substeps;
  ContactPush p{};
  p.count = static_cast<std::uint32_t>(m.bodies.size());
  p.rows = static_cast<std::uint32_t>(m.rows);
  p.cols = static_cast<std::uint32_t>(m.cols);
  p.pitch = p.cols;
  p.stride = static_cast<std::uint32_t>(m.nodes());
  p.dt = m.constants.dt;
  p.rim_x = static_cast<float>(m.cols - 1);
  p.rim_z = static_cast<float>(m.rows - 1);
  p.floor_y = static_cast<float>(-m.basin.floor_depth / h);
  p.land_y = static_cast<float>(m.basin.land_height / h);
  p.max_speed = static_cast<float>(POND_MAX_SPACINGS_PER_STEP / m.physics.dt);
  p.bounce_speed = static_cast<float>(POND_BOUNCE_GRAVITY_SUBSTEPS * m.physics.gravity * sub_dt / h);
  return p;
}

void resolve_contacts(WaterState& s, const WaterModel& m, std::int64_t step, int substep, float reach,
                      std::vector<NodeRect>* moved) {
  const ContactPush p = contact_push(m);
  std::array<BodyConstants, shared::kMaxBodies> sc{};
  std::array<BodyState, shared::kMaxBodies> sk{};
  for (std::uint32_t i = 0; i < p.count; ++i) {
    sc[i] = m.bodies[i].constants;
    if (!m.bodies[i].floating()) sk[i] = kinematic_state(m.bodies[i], step, substep, m.substeps, m.physics.dt);
  }
  for (std::uint32_t i = 0; i < p.count; ++i)
    if (sc[i].floating != 0u) exchange_with_water(s, m, s.bodies[i], sc[i]);
  move_bodies(s.bodies.data(), sc.data(), sk.data(), p.count, m.land.data(), p);
  for (std::uint32_t i = 0; i < p.count; ++i)
    if (sc[i].floating == 0u) {
      const NodeRect r = push_out(s, m, s.bodies[i], sc[i], reach);
      if (moved && r.row0 <= r.row1 && r.col0 <= r.col1) moved->push_back(r);
    }
  for (std::uint32_t i = 0; i < p.count; ++i) s.bodies[i] = shared::canonical_body(s.bodies[i]);
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
