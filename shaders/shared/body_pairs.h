// Body against body (shared/bodies.h, step 2), grid units: in each pass, every pair (a < b, in
// index order) of those that may touch at the pass's start whose spheres overlap, one of them
// floating, is separated along the line of centres in inverse proportion to the masses, with an
// impulse of restitution POND_RESTITUTION_BODY and Coulomb friction POND_FRICTION_BODY. Kinematic bodies have infinite mass: two of them feel nothing.
#ifndef POND_BODY_PAIRS_H
#define POND_BODY_PAIRS_H

#include "shared/body_land.h"  // contact_response

#define POND_PAIR_SLOP 1e-3f  // grid units: a smaller overlap is resolved but asks for no further pass

// The bodies (sb), their constants (sc) and a pass's pairs: parameters in C++, the shader's
// shared arrays in GLSL.
#ifdef __cplusplus
#define POND_BODIES_PARAMS BodyState *sb, const BodyConstants *sc,
#define POND_PAIRS_PARAM const PairMask *pairs,
namespace pond::shared {
#else
#define POND_BODIES_PARAMS
#define POND_PAIRS_PARAM
#endif

// Bodies a and b (constants ca, cb) separated where they overlap, with the impulse between them.
// True when they overlapped by more than POND_PAIR_SLOP: only such a pair asks for another pass
// (a pair left a rounding error apart would otherwise ask for every pass).
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
  return overlap > POND_PAIR_SLOP;
}

// Whether bodies a and b may touch: collide_pair()'s first tests on x and z, the same operations
// (so the same answer), without copying the two bodies in and out (GLSL's inout).
POND_BODY_FN bool pair_may_touch(float ax, float az, float bx, float bz, float ra, float rb) {
  POND_PRECISE float rs = ra + rb;
  POND_PRECISE float dx = bx - ax;
  POND_PRECISE float dz = bz - az;
  return abs(dx) < rs && abs(dz) < rs;
}

// Body a's PairMask for a pass: every b > a that may touch a at the pass's start (pair_may_touch).
// Found for every body first (in parallel on the GPU), then resolved in index order
// (resolve_pairs): a pair that another pair brings together within a pass waits for the next.
POND_BODY_FN PairMask pair_candidates(POND_BODIES_PARAMS uint a, uint count) {
  PairMask m;
  m.words[0] = 0u;
  m.words[1] = 0u;
  for (uint b = a + 1u; b < count; ++b)
    if (pair_may_touch(sb[a].x, sb[a].z, sb[b].x, sb[b].z, sc[a].radius, sc[b].radius))
      m.words[b >> 5u] |= 1u << (b & 31u);
  return m;
}

// One pass: every candidate pair (a, then b, ascending) collided. True when any overlapped by more
// than the slop.
POND_BODY_FN bool resolve_pairs(POND_BODIES_PARAMS POND_PAIRS_PARAM uint count, float bounce_speed) {
  bool touched = false;
  for (uint a = 0u; a < count; ++a)
    for (uint word = 0u; word < 2u; ++word)
      for (uint bits = pairs[a].words[word]; bits != 0u; bits &= bits - 1u) {
        const uint b = 32u * word + lowest_bit(bits);
        if (collide_pair(sb[a], sb[b], sc[a], sc[b], bounce_speed)) touched = true;
      }
  return touched;
}

#ifdef __cplusplus
// One pass over the pairs on one thread (the CPU's). True when any pair touched.
inline bool collide_pairs(BodyState* sb, const BodyConstants* sc, uint count, float bounce_speed) {
  PairMask pairs[kMaxBodies];
  for (uint a = 0u; a < count; ++a) pairs[a] = pair_candidates(sb, sc, a, count);
  return resolve_pairs(sb, sc, pairs, count, bounce_speed);
}
#endif

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#endif
