// Body against body (shared/bodies.h, step 2), grid units: every pair (a < b, in index order) of
// overlapping spheres, one of them floating, is separated along the line of centres in inverse
// proportion to the masses, with an impulse of restitution POND_RESTITUTION_BODY and Coulomb
// friction POND_FRICTION_BODY. Kinematic bodies have infinite mass: two of them feel nothing.
#ifndef POND_BODY_PAIRS_H
#define POND_BODY_PAIRS_H

#include "shared/body_land.h"  // contact_response

// The bodies (sb) and their constants (sc): parameters in C++, the shader's shared arrays in GLSL.
#ifdef __cplusplus
#define POND_BODIES_PARAMS BodyState *sb, const BodyConstants *sc,
namespace pond::shared {
#else
#define POND_BODIES_PARAMS
#endif

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
