// The bodies' motion through one substep (shared/bodies.h, step 2), grid units.
//
//  - A floating body's speed is clamped to POND_MAX_SPACINGS_PER_STEP spacings a step (flagged:
//    kBodyClamped); a kinematic one follows its path (the scene's paths are checked at load).
//  - The substep is split into n sub-iterations, so that no body moves by more than half a grid
//    spacing in one: the smallest body (radius 1) and a land cell cannot be crossed, whatever the
//    speed (no tunnelling).
//  - In each: every body moves (a floating one by v dt / n, a kinematic one a share of the way to
//    its scheduled position); then, up to POND_PAIR_PASSES times while a pair overlapped by more
//    than POND_PAIR_SLOP, the pairs (shared/body_pairs.h), then every floating body against the
//    land (shared/body_land.h). The land comes last: where it and another body disagree, it wins.
#ifndef POND_BODY_MOTION_H
#define POND_BODY_MOTION_H

#include "shared/bodies.h"

#define POND_ITERATIONS_PER_SPACING 2.0f  // sub-iterations per grid spacing of the largest move

#ifdef __cplusplus
namespace pond::shared {
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

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#endif
