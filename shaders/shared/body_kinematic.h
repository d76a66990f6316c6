// A kinematic body and the water (shared/bodies.h, step 3): after it has moved, every node that is
// not fixed and lies inside it moves vertically to its surface (the nearer cap) and takes its
// vertical velocity. It has infinite mass: the water never moves it, so nothing is reduced and the
// order of the nodes does not matter; the bodies are taken in scene order, each seeing the nodes
// the ones before it moved.
//
// Its footprint: the nodes whose actual position (j + ux, uy, i + uz) can be inside it. The springs
// can pull a node sideways by several spacings (a deep dent, a fast drag), so the footprint is
// bounded by the reach: the largest |ux| or |uz| of any node after the substep's integration,
// which the step kernels track (CPU and GPU). Rows [floor(z - e) - 1, ceil(z + e) + 1] and columns
// alike, e = r + reach; in it, a node whose rest position is farther than r (plus a rounding
// margin) from the sphere's axis even when moved by the reach on both axes is skipped before it is
// loaded (contact_may_touch).
#ifndef POND_BODY_KINEMATIC_H
#define POND_BODY_KINEMATIC_H

#include "shared/bodies.h"

// Below this squared half-chord a node is on the sphere's rim and counts as outside: the rsqrt
// seed is only exact for normal floats.
#define POND_CONTACT_MIN_H2 1e-20

#ifdef __cplusplus
namespace pond::shared {
#endif

// How far from a sphere's centre (radius r) the rest position of a node that can touch it lies
// along one axis: r + reach.
POND_BODY_FN float contact_extent(float r, float reach) {
  POND_PRECISE float e = r + reach;
  return e;
}

// The first and last index of a footprint along one axis (centre c, extent e = contact_extent):
// [floor(c - e) - 1, ceil(c + e) + 1] clipped to [0, last]; empty (first > last) off the grid,
// and the whole axis for a non-finite centre or reach (a blown-up state; the run then stops).
POND_BODY_FN int footprint_first(float c, float e) {
  POND_PRECISE float f = floor(c - e) - 1.0f;
  return f > 0.0f ? (f < 1.0e9f ? int(f) : 1000000000) : 0;
}
POND_BODY_FN int footprint_last(float c, float e, int last) {
  POND_PRECISE float f = ceil(c + e) + 1.0f;
  return f < float(last) ? (f > -1.0f ? int(f) : -1) : last;
}

// The squared distance from a sphere's axis (radius r) beyond which a node's actual position
// cannot be inside: (r + 1/16)^2, the 1/16 spacing far above every rounding of the tests.
POND_BODY_FN float contact_touch_limit2(float r) {
  POND_PRECISE float l = r + 0.0625f;
  POND_PRECISE float l2 = l * l;
  return l2;
}

// Whether the node resting at (j, i) can lie inside the sphere centred over (bx, bz) when no node
// moves by more than `reach` along x or z: its rest offsets shrunk by the reach, then against
// contact_touch_limit2. Integer positions and the reach only: no load.
POND_BODY_FN bool contact_may_touch(int j, int i, float bx, float bz, float reach, float limit2) {
  POND_PRECISE float ax = abs(float(j) - bx) - reach;
  POND_PRECISE float az = abs(float(i) - bz) - reach;
  ax = ax > 0.0f ? ax : 0.0f;
  az = az > 0.0f ? az : 0.0f;
  POND_PRECISE float d2 = ax * ax + az * az;
  return d2 < limit2;
}

// Half the vertical chord of the sphere (centre bx, bz, squared radius r2) at the horizontal
// position (x, z), or 0 where the chord is empty: a node there with |y - by| < the result is inside.
POND_BODY_FN float contact_half_height(float x, float z, float bx, float bz, float r2) {
  POND_PRECISE float dx = x - bx;
  POND_PRECISE float dz = z - bz;
  POND_PRECISE float d2 = dx * dx + dz * dz;
  POND_PRECISE float h2 = r2 - d2;
  if (!(h2 > POND_CONTACT_MIN_H2)) return 0.0f;
  POND_PRECISE float half_height = h2 * rsqrt_exact(h2, kRsqrtStepsExact);
  return half_height;
}

// The height a node at height y inside the sphere (centre height by, half chord `half_height`)
// moves to: the nearer cap.
POND_BODY_FN float contact_surface(float y, float by, float half_height) {
  POND_PRECISE float up = by + half_height;
  POND_PRECISE float down = by - half_height;
  return y >= by ? up : down;
}

// Whether a node at height y is strictly inside the chord.
POND_BODY_FN bool contact_inside(float y, float by, float half_height) {
  POND_PRECISE float dy = y - by;
  return dy < half_height && -dy < half_height;
}

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#endif
