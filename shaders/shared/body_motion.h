// The bodies' motion through one substep (shared/bodies.h, step 2), grid units.
//
//  - A floating body's speed is clamped to POND_MAX_SPACINGS_PER_STEP spacings a step (flagged:
//    kBodyClamped); a kinematic one follows its path (the scene's paths are checked at load).
//  - The substep is split into n sub-iterations, so that no body moves by more than half a grid
//    spacing in one: the smallest body (radius 1) and a land cell cannot be crossed, whatever the
//    speed (no tunnelling).
//  - In each: every body moves (a floating one by v dt / n, a kinematic one a share of the way to
//    its scheduled position); then, up to POND_PAIR_PASSES times while a pair touched: every pair
//    (a < b, in index order) of overlapping spheres is separated along the line of centres in
//    inverse proportion to the masses, with an impulse of restitution POND_RESTITUTION_BODY and
//    Coulomb friction POND_FRICTION_BODY (kinematic bodies have infinite mass: two of them feel
//    nothing), then every floating body is pushed out of the land: the pond's walls (the rim,
//    continued upward, so no ball leaves the pond), the floor and the land cells (islands) up to
//    the land's top, restitution POND_RESTITUTION_LAND and friction POND_FRICTION_LAND. The land
//    comes last: where it and another body disagree, the land wins.
// The functions take the bodies' arrays as parameters in C++ and as the shader's globals in GLSL
// (POND_BODIES_PARAMS); the land as `land` (shared/bodies.h: its row runs).
#ifndef POND_BODY_MOTION_H
#define POND_BODY_MOTION_H

#include "shared/bodies.h"

#define POND_ITERATIONS_PER_SPACING 2.0f  // sub-iterations per grid spacing of the largest move
#define POND_MIN_DISTANCE2 1e-12          // below this squared distance a contact has no direction

#ifdef __cplusplus
#define POND_LAND_PARAM const uint *land,
#define POND_LAND_ARG land,
#define POND_BODIES_PARAMS BodyState *sb, const BodyConstants *sc,
#define POND_BODIES_ARGS sb, sc,
namespace pond::shared {
#else
#define POND_LAND_PARAM
#define POND_LAND_ARG
#define POND_BODIES_PARAMS
#define POND_BODIES_ARGS
#endif

// Before the sub-iterations: clamps a floating body's speed; a kinematic body takes its path's
// velocity (k: where the path puts it at the end of the substep). Returns the largest distance the
// body moves along an axis in this substep.
POND_BODY_FN float body_prepare(POND_INOUT(BodyState) b, BodyConstants c, BodyState k, float max_speed, float dt) {
  POND_PRECISE float ax, ay, az;
  if (c.floating != 0u) {
    POND_PRECISE float v2 = b.vx * b.vx;
    POND_PRECISE float t = b.vy * b.vy;
    v2 = v2 + t;
    t = b.vz * b.vz;
    v2 = v2 + t;
    POND_PRECISE float m2 = max_speed * max_speed;
    if (v2 > m2) {
      POND_PRECISE float s = max_speed * rsqrt_exact(v2, kRsqrtStepsExact);
      t = b.vx * s; b.vx = t;
      t = b.vy * s; b.vy = t;
      t = b.vz * s; b.vz = t;
      b.flags = b.flags | kBodyClamped;
    }
    ax = abs(b.vx) * dt;
    ay = abs(b.vy) * dt;
    az = abs(b.vz) * dt;
  } else {
    ax = abs(k.x - b.x);
    ay = abs(k.y - b.y);
    az = abs(k.z - b.z);
    b.vx = k.vx;
    b.vy = k.vy;
    b.vz = k.vz;
  }
  POND_PRECISE float most = ax > ay ? ax : ay;
  return most > az ? most : az;
}

// How many sub-iterations the largest move `most` needs (at least 1).
POND_BODY_FN int motion_iterations(float most) {
  POND_PRECISE float n = most * POND_ITERATIONS_PER_SPACING;
  n = ceil(n);
  return n > 1.0f ? (n < float(POND_MAX_ITERATIONS) ? int(n) : POND_MAX_ITERATIONS) : 1;
}

// One sub-iteration's move, `remaining` sub-iterations (this one included) before the substep ends:
// a floating body by v * dt_n; a kinematic body 1 / remaining of the way to k, the last exactly.
POND_BODY_FN BodyState body_advance(BodyState b, BodyConstants c, BodyState k, float dt_n, int remaining) {
  POND_PRECISE float t;
  if (c.floating != 0u) {
    t = b.vx * dt_n; t = b.x + t; b.x = t;
    t = b.vy * dt_n; t = b.y + t; b.y = t;
    t = b.vz * dt_n; t = b.z + t; b.z = t;
  } else if (remaining <= 1) {
    b.x = k.x;
    b.y = k.y;
    b.z = k.z;
  } else {
    POND_PRECISE float share = inv_exact(float(remaining));
    t = k.x - b.x; t = t * share; t = b.x + t; b.x = t;
    t = k.y - b.y; t = t * share; t = b.y + t; b.y = t;
    t = k.z - b.z; t = t * share; t = b.z + t; b.z = t;
  }
  return b;
}

// The velocity response of a contact with unit normal n (from the other side toward b) whose other
// side has infinite mass and no velocity: no normal velocity into it, a bounce of `restitution`
// above bounce_speed, Coulomb friction on the tangential velocity.
POND_BODY_FN void contact_response(POND_INOUT(BodyState) b, float nx, float ny, float nz, float restitution,
                                   float friction, float bounce_speed) {
  POND_PRECISE float vn = b.vx * nx;
  POND_PRECISE float t = b.vy * ny;
  vn = vn + t;
  t = b.vz * nz;
  vn = vn + t;
  if (!(vn < 0.0f)) return;
  POND_PRECISE float e = -vn > bounce_speed ? restitution : 0.0f;
  POND_PRECISE float jn = 1.0f + e;
  jn = jn * vn;
  jn = -jn;  // the normal impulse per unit mass, > 0
  POND_PRECISE float tx = nx * vn;
  tx = b.vx - tx;
  POND_PRECISE float ty = ny * vn;
  ty = b.vy - ty;
  POND_PRECISE float tz = nz * vn;
  tz = b.vz - tz;
  POND_PRECISE float t2 = tx * tx;
  t = ty * ty;
  t2 = t2 + t;
  t = tz * tz;
  t2 = t2 + t;
  POND_PRECISE float keep = 1.0f;  // the share of the tangential velocity friction leaves
  if (t2 > POND_MIN_DISTANCE2) {
    POND_PRECISE float inv_vt = rsqrt_exact(t2, kRsqrtStepsExact);
    POND_PRECISE float stop = friction * jn;
    stop = stop * inv_vt;
    keep = 1.0f - stop;
    keep = keep > 0.0f ? keep : 0.0f;
  }
  POND_PRECISE float vn_after = vn + jn;
  t = tx * keep; POND_PRECISE float u = nx * vn_after; t = t + u; b.vx = t;
  t = ty * keep; u = ny * vn_after; t = t + u; b.vy = t;
  t = tz * keep; u = nz * vn_after; t = t + u; b.vz = t;
}

// Pushes b out of the land by `depth` along the unit normal n, then its velocity response.
POND_BODY_FN void land_contact(POND_INOUT(BodyState) b, float nx, float ny, float nz, float depth, float bounce_speed) {
  POND_PRECISE float t;
  t = nx * depth; t = b.x + t; b.x = t;
  t = ny * depth; t = b.y + t; b.y = t;
  t = nz * depth; t = b.z + t; b.z = t;
  contact_response(b, nx, ny, nz, POND_RESTITUTION_LAND, POND_FRICTION_LAND, bounce_speed);
}

// b against a column of land [x0, x1] x [z0, z1] up to `top` (it reaches down past the floor).
// True when they touched.
POND_BODY_FN bool box_contact(POND_INOUT(BodyState) b, BodyConstants c, float x0, float x1, float z0, float z1,
                              float top, float bounce_speed) {
  POND_PRECISE float px = b.x > x0 ? (b.x < x1 ? b.x : x1) : x0;
  POND_PRECISE float py = b.y < top ? b.y : top;
  POND_PRECISE float pz = b.z > z0 ? (b.z < z1 ? b.z : z1) : z0;
  POND_PRECISE float dx = b.x - px;
  POND_PRECISE float dy = b.y - py;
  POND_PRECISE float dz = b.z - pz;
  POND_PRECISE float d2 = dx * dx;
  POND_PRECISE float t = dy * dy;
  d2 = d2 + t;
  t = dz * dz;
  d2 = d2 + t;
  if (!(d2 < c.radius2)) return false;
  if (d2 > POND_MIN_DISTANCE2) {
    POND_PRECISE float inv_d = rsqrt_exact(d2, kRsqrtStepsExact);
    POND_PRECISE float d = d2 * inv_d;
    POND_PRECISE float depth = c.radius - d;
    POND_PRECISE float nx = dx * inv_d;
    POND_PRECISE float ny = dy * inv_d;
    POND_PRECISE float nz = dz * inv_d;
    land_contact(b, nx, ny, nz, depth, bounce_speed);
  } else {  // the centre inside the land: out through its top
    POND_PRECISE float depth = top - b.y;
    depth = depth + c.radius;
    land_contact(b, 0.0f, 1.0f, 0.0f, depth, bounce_speed);
  }
  return true;
}

// A floating body against the pond's walls, its floor and the land cells near it. True when it
// touched any.
POND_BODY_FN bool collide_land(POND_LAND_PARAM POND_INOUT(BodyState) b, BodyConstants c, ContactPush p) {
  bool touched = false;
  const float r = c.radius;
  POND_PRECISE float lim = p.rim_x - r;
  if (b.x < r) { land_contact(b, 1.0f, 0.0f, 0.0f, r - b.x, p.bounce_speed); touched = true; }
  if (b.x > lim) { land_contact(b, -1.0f, 0.0f, 0.0f, b.x - lim, p.bounce_speed); touched = true; }
  lim = p.rim_z - r;
  if (b.z < r) { land_contact(b, 0.0f, 0.0f, 1.0f, r - b.z, p.bounce_speed); touched = true; }
  if (b.z > lim) { land_contact(b, 0.0f, 0.0f, -1.0f, b.z - lim, p.bounce_speed); touched = true; }
  lim = p.floor_y + r;
  if (b.y < lim) { land_contact(b, 0.0f, 1.0f, 0.0f, lim - b.y, p.bounce_speed); touched = true; }
  POND_PRECISE float bottom = b.y - r;
  if (!(bottom < p.land_y)) return touched;
  const int last_row = int(land[0]) - 1;
  const uint runs = POND_LAND_HEADER(land[0]);
  POND_PRECISE float lo = b.x - r;
  POND_PRECISE float hi = b.x + r;
  POND_PRECISE float zlo = b.z - r;
  POND_PRECISE float zhi = b.z + r;
  const int i0 = clip_index(floor(zlo), last_row), i1 = clip_index(floor(zhi), last_row);
  for (int i = i0; i <= i1; ++i)
    for (uint k = land[1 + i]; k < land[2 + i]; ++k) {
      const float x0 = float(land[runs + 2u * k]), x1 = float(land[runs + 2u * k + 1u]);
      if (x1 < lo) continue;
      if (x0 > hi) break;
      if (box_contact(b, c, x0, x1, float(i), float(i + 1), p.land_y, p.bounce_speed)) touched = true;
    }
  return touched;
}

// Bodies a and b (constants ca, cb) separated where they overlap, with the impulse between them.
// True when they touched.
POND_BODY_FN bool collide_pair(POND_INOUT(BodyState) a, POND_INOUT(BodyState) b, BodyConstants ca, BodyConstants cb,
                               float bounce_speed) {
  POND_PRECISE float wsum = ca.inv_mass + cb.inv_mass;
  if (!(wsum > 0.0f)) return false;  // two kinematic bodies
  POND_PRECISE float dx = b.x - a.x;
  POND_PRECISE float dy = b.y - a.y;
  POND_PRECISE float dz = b.z - a.z;
  POND_PRECISE float rs = ca.radius + cb.radius;
  POND_PRECISE float t = abs(dx);
  if (!(t < rs)) return false;
  t = abs(dz);
  if (!(t < rs)) return false;
  POND_PRECISE float d2 = dx * dx;
  t = dy * dy;
  d2 = d2 + t;
  t = dz * dz;
  d2 = d2 + t;
  POND_PRECISE float rs2 = rs * rs;
  if (!(d2 < rs2)) return false;
  POND_PRECISE float nx = 0.0f, ny = 1.0f, nz = 0.0f, d = 0.0f;
  if (d2 > POND_MIN_DISTANCE2) {
    POND_PRECISE float inv_d = rsqrt_exact(d2, kRsqrtStepsExact);
    d = d2 * inv_d;
    nx = dx * inv_d;
    ny = dy * inv_d;
    nz = dz * inv_d;
  }
  POND_PRECISE float inv_wsum = inv_exact(wsum);
  POND_PRECISE float overlap = rs - d;
  POND_PRECISE float sa = overlap * ca.inv_mass;
  sa = sa * inv_wsum;
  POND_PRECISE float sb_ = overlap * cb.inv_mass;
  sb_ = sb_ * inv_wsum;
  t = nx * sa; t = a.x - t; a.x = t;
  t = ny * sa; t = a.y - t; a.y = t;
  t = nz * sa; t = a.z - t; a.z = t;
  t = nx * sb_; t = b.x + t; b.x = t;
  t = ny * sb_; t = b.y + t; b.y = t;
  t = nz * sb_; t = b.z + t; b.z = t;
  // The impulse: b's velocity relative to a's, as a contact of b against a resting a of mass
  // ratio; each takes its share by inverse mass.
  BodyState rel = b;
  t = b.vx - a.vx; rel.vx = t;
  t = b.vy - a.vy; rel.vy = t;
  t = b.vz - a.vz; rel.vz = t;
  BodyState before = rel;
  contact_response(rel, nx, ny, nz, POND_RESTITUTION_BODY, POND_FRICTION_BODY, bounce_speed);
  POND_PRECISE float jx = rel.vx - before.vx;  // the change of the relative velocity
  POND_PRECISE float jy = rel.vy - before.vy;
  POND_PRECISE float jz = rel.vz - before.vz;
  POND_PRECISE float fa = ca.inv_mass * inv_wsum;
  POND_PRECISE float fb = cb.inv_mass * inv_wsum;
  t = jx * fa; t = a.vx - t; a.vx = t;
  t = jy * fa; t = a.vy - t; a.vy = t;
  t = jz * fa; t = a.vz - t; a.vz = t;
  t = jx * fb; t = b.vx + t; b.vx = t;
  t = jy * fb; t = b.vy + t; b.vy = t;
  t = jz * fb; t = b.vz + t; b.vz = t;
  return true;
}

// Whether bodies a and b may touch: collide_pair()'s first tests on x and z, the same operations
// (so the same answer), without copying the two bodies in and out (GLSL's inout).
POND_BODY_FN bool pair_may_touch(float ax, float az, float bx, float bz, float ra, float rb) {
  POND_PRECISE float rs = ra + rb;
  POND_PRECISE float dx = bx - ax;
  POND_PRECISE float dz = bz - az;
  return abs(dx) < rs && abs(dz) < rs;
}

// One pass over the pairs of bodies in index order. True when any pair touched.
POND_BODY_FN bool collide_pairs(POND_BODIES_PARAMS uint count, float bounce_speed) {
  bool touched = false;
  for (uint a = 0u; a < count; ++a)
    for (uint b = a + 1u; b < count; ++b)
      if (pair_may_touch(sb[a].x, sb[a].z, sb[b].x, sb[b].z, sc[a].radius, sc[b].radius) &&
          collide_pair(sb[a], sb[b], sc[a], sc[b], bounce_speed))
        touched = true;
  return touched;
}

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#endif
