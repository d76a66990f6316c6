// A floating body and the water (shared/bodies.h, step 1), grid units. Below its waterline the
// water passes through a floating ball: the nodes stay where the water would be (the opaque ball
// hides them), so the surface under the ball is still the water's and the ball reads it there.
//
//  - The water at the body: a tent kernel of half-width r over the nodes that are not fixed,
//    weight w = (1 - |j - x|/r)(1 - |i - z|/r) by rest position. It gives the level L (the
//    weighted mean height), the slope (a weighted least-squares fit along x and along z) and the
//    water's velocity (the weighted mean). The sums are reductions in one fixed order: node (i, j)
//    belongs to lane (i % 8) * 8 + j % 8, each lane adds its nodes in row-major order, then the
//    lanes are added in lane order; the lanes hang on the grid, so the bits do not depend on the
//    footprint.
//  - Archimedes: the sphere's part below the plane y = L is a cap of height hs = L - (y - r) in
//    [0, 2r], its volume fraction f = hs^2 (3r - hs) / (4 r^3). Buoyancy rho_w g V f acts along the
//    surface's normal (-gx, 1, -gz) / |..|: a slope pushes the ball sideways, as the pressure
//    gradient under a wave does. Its reaction goes to the bed (an external force, like gravity):
//    a ball at rest leaves the water flat.
//  - Drag and displacement: a linear drag against the water's velocity, rate k = drag_dt * f, on
//    the velocity the body starts the substep with (before this substep's weight and buoyancy,
//    which a contact may take away again: a ball resting on the floor drags nothing), solved implicitly with the nodes as the other mass (effective mass m (sum w)^2 / sum w^2), so
//    the relative velocity only ever shrinks: v_b' = v_b - k dv / (1 + k (1 + M / m_eff)). The
//    opposite impulse goes into the nodes in proportion to their weights: sideways all of it, into
//    the free nodes only (a vertical-only node's wall takes it); vertically the share of the ball
//    above the level, 1 - f, into every node under the ball (a ball moving through the surface
//    pushes the water it displaces: its rings), and the rest to the bed, as buoyancy's. The
//    surface here stands for the whole column, which hands a deep body's push on to the floor; the
//    membrane has no restoring force to give back a level pushed down (a ball sinking under the
//    water would dig a lasting pit).
#ifndef POND_BODY_WATER_H
#define POND_BODY_WATER_H

#include "shared/bodies.h"

// Below this kernel weight there is no water under the body (over land); below this variance of
// the kernel's positions along an axis the slope along it is taken as 0 (too few nodes to fit it).
#define POND_WATER_MIN_WEIGHT 1e-4
#define POND_WATER_MIN_VARIANCE 0.05

#ifdef __cplusplus
namespace pond::shared {
#endif

// The kernel's weighted sums over the water nodes (not fixed) under a body.
struct WaterMoments {
  float w, w2;            // sum of w and of w^2
  float free_w, free_w2;  // the same over the free nodes (those that move sideways)
  float y;                // sum of w * uy
  float dx, dz;           // sum of w * (j - x), w * (i - z)
  float dxx, dzz;         // sum of w * (j - x)^2, w * (i - z)^2
  float dxy, dzy;         // sum of w * (j - x) * uy, w * (i - z) * uy
  float vx, vy, vz;       // sum of w * v
};

// What the water does to a floating body in one substep: its new velocity, and the velocity each
// node under it gains per unit of kernel weight (cx and cz for the free nodes only).
struct WaterExchange {
  BodyState body;
  float cx, cy, cz;
  uint wet;  // 1: the body is in the water (the nodes take cx, cy, cz); 0: they are left alone
};

// The kernel's first and last index along one axis: the nodes within r of the centre c.
POND_BODY_FN int water_first(float c, float r, int last) {
  POND_PRECISE float f = ceil(c - r);
  return clip_index(f, last);
}
POND_BODY_FN int water_last(float c, float r, int last) {
  POND_PRECISE float f = floor(c + r);
  return clip_index(f, last);
}

// The kernel's weight of the node resting at (j, i) for a body over (bx, bz); 0 outside it.
POND_BODY_FN float water_weight(int j, int i, float bx, float bz, float inv_r) {
  POND_PRECISE float ax = abs(float(j) - bx) * inv_r;
  POND_PRECISE float az = abs(float(i) - bz) * inv_r;
  POND_PRECISE float wx = 1.0f - ax;
  POND_PRECISE float wz = 1.0f - az;
  if (!(wx > 0.0f && wz > 0.0f)) return 0.0f;
  POND_PRECISE float w = wx * wz;
  return w;
}

POND_BODY_FN WaterMoments moments_zero() {
  WaterMoments m;
  m.w = 0.0f; m.w2 = 0.0f; m.free_w = 0.0f; m.free_w2 = 0.0f; m.y = 0.0f; m.dx = 0.0f; m.dz = 0.0f;
  m.dxx = 0.0f; m.dzz = 0.0f; m.dxy = 0.0f; m.dzy = 0.0f; m.vx = 0.0f; m.vy = 0.0f; m.vz = 0.0f;
  return m;
}

// a + the moments of the node resting at (j, i) (weight w > 0 for the body over (bx, bz); height
// y, velocity v; `free_node`: it moves sideways).
POND_BODY_FN WaterMoments moments_add_node(WaterMoments a, float w, int j, int i, float bx, float bz, float y, float vx,
                                           float vy, float vz, bool free_node) {
  POND_PRECISE float dx = float(j) - bx;
  POND_PRECISE float dz = float(i) - bz;
  POND_PRECISE float w2 = w * w;
  POND_PRECISE float wdx = w * dx;
  POND_PRECISE float wdz = w * dz;
  POND_PRECISE float t;
  t = a.w + w; a.w = t;
  t = a.w2 + w2; a.w2 = t;
  if (free_node) {
    t = a.free_w + w; a.free_w = t;
    t = a.free_w2 + w2; a.free_w2 = t;
  }
  t = w * y; t = a.y + t; a.y = t;
  t = a.dx + wdx; a.dx = t;
  t = a.dz + wdz; a.dz = t;
  t = wdx * dx; t = a.dxx + t; a.dxx = t;
  t = wdz * dz; t = a.dzz + t; a.dzz = t;
  t = wdx * y; t = a.dxy + t; a.dxy = t;
  t = wdz * y; t = a.dzy + t; a.dzy = t;
  t = w * vx; t = a.vx + t; a.vx = t;
  t = w * vy; t = a.vy + t; a.vy = t;
  t = w * vz; t = a.vz + t; a.vz = t;
  return a;
}

POND_BODY_FN WaterMoments moments_add(WaterMoments a, WaterMoments b) {
  POND_PRECISE float t;
  t = a.w + b.w; a.w = t;
  t = a.w2 + b.w2; a.w2 = t;
  t = a.free_w + b.free_w; a.free_w = t;
  t = a.free_w2 + b.free_w2; a.free_w2 = t;
  t = a.y + b.y; a.y = t;
  t = a.dx + b.dx; a.dx = t;
  t = a.dz + b.dz; a.dz = t;
  t = a.dxx + b.dxx; a.dxx = t;
  t = a.dzz + b.dzz; a.dzz = t;
  t = a.dxy + b.dxy; a.dxy = t;
  t = a.dzy + b.dzy; a.dzy = t;
  t = a.vx + b.vx; a.vx = t;
  t = a.vy + b.vy; a.vy = t;
  t = a.vz + b.vz; a.vz = t;
  return a;
}

// The submerged volume fraction of a sphere (centre height y, radius r, 1 / (4 r^3)) under the
// level L: a cap of height hs = L - y + r clipped to [0, 2r].
POND_BODY_FN float submerged_fraction(float level, float y, float r, float inv_4r3) {
  POND_PRECISE float hs = level - y;
  hs = hs + r;
  POND_PRECISE float d = r + r;
  hs = hs > 0.0f ? (hs < d ? hs : d) : 0.0f;
  POND_PRECISE float rest = 3.0f * r;
  rest = rest - hs;
  POND_PRECISE float f = hs * hs;
  f = f * rest;
  f = f * inv_4r3;
  return f;
}

// The slope of the water along one axis from the moments: cov(d, y) / var(d), or 0 when the
// kernel's nodes hardly spread along it.
POND_BODY_FN float water_slope(float sd, float sdd, float sdy, float inv_w, float level) {
  POND_PRECISE float mean = sd * inv_w;
  POND_PRECISE float var = sdd * inv_w;
  POND_PRECISE float mm = mean * mean;
  var = var - mm;
  if (!(var > POND_WATER_MIN_VARIANCE)) return 0.0f;
  POND_PRECISE float cov = sdy * inv_w;
  POND_PRECISE float ml = mean * level;
  cov = cov - ml;
  POND_PRECISE float g = cov * inv_exact(var);
  return g;
}

// The implicit drag's change of a body's velocity along one axis: relative velocity `rel`, rate
// k (times dt) and q = M / m_eff.
POND_BODY_FN float drag_change(float rel, float k, float q) {
  POND_PRECISE float d = 1.0f + q;
  d = k * d;
  d = 1.0f + d;
  POND_PRECISE float change = k * rel;
  change = -change;
  change = change * inv_exact(d);
  return change;
}

// One substep of the water on floating body b (constants c), from the moments m of the water under
// it: the drag against the water's velocity, on the velocity b starts the substep with; then
// gravity and buoyancy along the normal. The drag comes first so that it never acts on the share of
// this substep's weight that a contact (the floor, the land, a body under it) takes away afterwards:
// a ball resting on the floor starts each substep at rest, so still water exchanges nothing with it.
POND_BODY_FN WaterExchange water_exchange(WaterMoments m, BodyState b, BodyConstants c) {
  WaterExchange e;
  e.cx = 0.0f;
  e.cy = 0.0f;
  e.cz = 0.0f;
  e.wet = 0u;
  POND_PRECISE float f = 0.0f;
  POND_PRECISE float gx = 0.0f;
  POND_PRECISE float gz = 0.0f;
  if (m.w > POND_WATER_MIN_WEIGHT) {  // else no water under it
    POND_PRECISE float inv_w = inv_exact(m.w);
    POND_PRECISE float level = m.y * inv_w;
    f = submerged_fraction(level, b.y, c.radius, c.inv_4r3);
    if (f > 0.0f) {  // else above the water
      e.wet = 1u;
      gx = water_slope(m.dx, m.dxx, m.dxy, inv_w, level);
      gz = water_slope(m.dz, m.dzz, m.dzy, inv_w, level);

      // The drag, against the water's mean velocity; the nodes take the opposite impulse.
      POND_PRECISE float k = c.drag_dt * f;
      POND_PRECISE float wvy = m.vy * inv_w;
      // The surface takes the vertical reaction in the share of the ball above the level; the
      // bed takes the rest, as it takes buoyancy's (a ball deep in the water moves no surface).
      POND_PRECISE float share = 1.0f - f;
      POND_PRECISE float per = c.body_over_node * inv_w;
      per = per * share;
      POND_PRECISE float qy = per * m.w2;
      qy = qy * inv_w;
      POND_PRECISE float rel = b.vy - wvy;
      POND_PRECISE float dvy = drag_change(rel, k, qy);
      POND_PRECISE float t = -dvy;
      e.cy = t * per;
      POND_PRECISE float wvx = m.vx * inv_w;
      POND_PRECISE float wvz = m.vz * inv_w;
      POND_PRECISE float qh = 0.0f;
      POND_PRECISE float per_free = 0.0f;
      if (m.free_w > POND_WATER_MIN_WEIGHT) {
        POND_PRECISE float inv_free = inv_exact(m.free_w);
        qh = c.body_over_node * m.free_w2;
        qh = qh * inv_free;
        qh = qh * inv_w;
        per_free = c.body_over_node * inv_free;
      }
      rel = b.vx - wvx;
      POND_PRECISE float dvx = drag_change(rel, k, qh);
      rel = b.vz - wvz;
      POND_PRECISE float dvz = drag_change(rel, k, qh);
      t = b.vx + dvx; b.vx = t;
      t = b.vy + dvy; b.vy = t;
      t = b.vz + dvz; b.vz = t;
      t = -dvx;
      e.cx = t * per_free;
      t = -dvz;
      e.cz = t * per_free;
    }
  }
  // Gravity, then buoyancy along the surface's normal (-gx, 1, -gz) / |..|.
  POND_PRECISE float vy = b.vy - c.gravity_dt;
  b.vy = vy;
  if (f > 0.0f) {
    POND_PRECISE float n2 = gx * gx;
    POND_PRECISE float gz2 = gz * gz;
    n2 = n2 + gz2;
    n2 = n2 + 1.0f;
    POND_PRECISE float push = c.buoyancy_dt * f;
    push = push * rsqrt_exact(n2, kRsqrtStepsExact);
    POND_PRECISE float t = push * gx;
    t = b.vx - t; b.vx = t;
    t = b.vy + push; b.vy = t;
    t = push * gz;
    t = b.vz - t; b.vz = t;
  }
  e.body = canonical_body(b);
  e.cx = plus_zero(e.cx);
  e.cy = plus_zero(e.cy);
  e.cz = plus_zero(e.cz);
  return e;
}

// A node's velocity v after the exchange: v + per_weight * w.
POND_BODY_FN float water_kick(float v, float per_weight, float w) {
  POND_PRECISE float t = per_weight * w;
  t = v + t;
  return t;
}

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#endif
