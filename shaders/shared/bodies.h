// The bodies in the water (spheres), declared once for GLSL (water_contact.comp) and C++ (the CPU
// solver's sim/contact.cpp and the GPU solver), so both run the same contact with the same bits.
//
// The contact, after every substep, body after body in scene order (grid units throughout):
//  1. The body moves: a floating body by its velocity (p += v * dt), a kinematic one to its
//     path's position at the end of the substep.
//  2. Its footprint: the nodes whose actual position (j + ux, uy, i + uz) can be inside it. The
//     springs can pull a node sideways by several spacings (a deep dent, a fast drag), so the
//     footprint is bounded by the reach: the largest |ux| or |uz| of any node after the substep's
//     integration, which the step kernels track (CPU and GPU). Rows [floor(z - e) - 1,
//     ceil(z + e) + 1] and columns alike, e = r + reach; in it, a node whose rest position is
//     farther than r (plus a rounding margin) from the sphere's axis even when moved by the reach
//     on both axes is skipped before it is loaded (contact_may_touch). A node that is not fixed
//     lies inside the body when its actual position does (contact_half_height).
//  3. A floating body and the nodes inside it collide perfectly inelastically along y: they all
//     take the common velocity  v_c = (M vb + m sum(v_i)) / (M + N m), which conserves their
//     momentum and is stable for any mass ratio. The sum is a reduction in one fixed order: node
//     (i, j) belongs to lane (i % 8) * 8 + j % 8 of the kContactLanes = 64 lanes, each lane adds
//     its nodes in row-major order, then the lanes' sums are added in lane order. The lanes hang on
//     the grid, not on the footprint, so the bits do not depend on how far the footprint reaches
//     (nodes outside the body add nothing). A kinematic body has infinite mass: v_c = vb.
//  4. Every node inside moves vertically to the sphere's surface (the nearer of the upper and
//     lower cap) and takes v_c; the body takes v_c, then gravity: vy = v_c - gravity_dt (so a body
//     at rest on the water has vy = 0 between substeps).
#ifndef POND_BODIES_H
#define POND_BODIES_H

#include "shared/exact_math.h"

#define POND_CONTACT_LANES 64  // the reduction's lanes (partial sums), whatever the invocations
#define POND_CONTACT_LANE_SIDE 8  // lane of node (i, j): (i % 8) * 8 + j % 8
#define POND_CONTACT_LOCAL_X 64  // default invocations of water_contact.comp; the solver sets it (below)
#define POND_SPEC_CONTACT_LOCAL_X 0  // specialization constant: water_contact.comp's local_size_x

// Bindings of water_contact.comp.
#define POND_CONTACT_BINDING_STATE 0      // storage buffer: the current state, float[] (water_gpu.h)
#define POND_CONTACT_BINDING_KINDS4 1     // uniform texel buffer, R8G8B8A8_UINT view of the kinds (nodes 4t..4t+3)
#define POND_CONTACT_BINDING_BODIES 2     // storage buffer: BodyState[], one per body
#define POND_CONTACT_BINDING_CONSTANTS 3  // storage buffer: BodyConstants[], one per body
#define POND_CONTACT_BINDING_SCHEDULE 4   // storage buffer: BodyState[], kinematic bodies per substep
#define POND_CONTACT_BINDING_REACH 5     // storage buffer: uint, the reach's float bits (water_step.comp)
#define POND_CONTACT_BINDING_STATE1 6     // uniform texel buffer, R32_SFLOAT view of the current state
#define POND_CONTACT_BINDINGS 7

#ifdef __cplusplus
#define POND_BODY_CONST inline constexpr
namespace pond::shared {
#else
#define POND_BODY_CONST const
#endif

POND_BODY_CONST int kContactLanes = POND_CONTACT_LANES;

// A body's centre and velocity in grid units (world / spacing): the state of one body.
struct BodyState {
  float x, y, z;
  float vx, vy, vz;
};

// What does not change while a body moves, rounded once from double on the CPU.
struct BodyConstants {
  float radius;
  float radius2;         // radius * radius
  float node_over_body;  // node mass / body mass (0 for a kinematic body)
  float gravity_dt;      // gravity * dt / spacing: the velocity gravity adds in a substep
  uint floating;         // 1: floating, 0: kinematic
};

// Push constants of water_contact.comp: one substep's contact.
struct ContactPush {
  uint count;           // bodies
  uint rows;
  uint cols;
  uint pitch;           // nodes between two rows of the state (water_gpu.h)
  uint stride;          // floats between the state's component arrays
  uint schedule_first;  // the entry of body 0 for this substep in the schedule
  float dt;             // substep length
  float rim_x;          // (cols - 1) and (rows - 1): a floating body's centre stays over the grid
  float rim_z;
};

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#undef POND_BODY_CONST

// Below this squared half-chord a node is on the sphere's rim and counts as outside: the rsqrt
// seed is only exact for normal floats.
#define POND_CONTACT_MIN_H2 1e-20

#ifdef __cplusplus
#include <cmath>
#define POND_BODY_FN inline
namespace pond::shared {
using std::abs;
using std::ceil;
using std::floor;
#else
#define POND_BODY_FN
#endif

// A floating body's motion through a substep (step 1 above). Its centre stays over the grid: the
// rim (x in [0, rim_x], z in [0, rim_z]) stops it horizontally.
POND_BODY_FN BodyState contact_move_floating(BodyState b, float dt, float rim_x, float rim_z) {
  POND_PRECISE float x = b.x + b.vx * dt;
  POND_PRECISE float y = b.y + b.vy * dt;
  POND_PRECISE float z = b.z + b.vz * dt;
  b.x = x;
  b.y = y;
  b.z = z;
  if (b.x < 0.0f) { b.x = 0.0f; b.vx = 0.0f; }
  if (b.x > rim_x) { b.x = rim_x; b.vx = 0.0f; }
  if (b.z < 0.0f) { b.z = 0.0f; b.vz = 0.0f; }
  if (b.z > rim_z) { b.z = rim_z; b.vz = 0.0f; }
  return b;
}

// How far from a sphere's centre (radius r) the rest position of a node that can touch it lies
// along one axis: r + reach (step 2).
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

// The reduction lane of node (i, j), both >= 0 (step 3).
POND_BODY_FN int contact_lane(int i, int j) {
  return (i % POND_CONTACT_LANE_SIDE) * POND_CONTACT_LANE_SIDE + j % POND_CONTACT_LANE_SIDE;
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

// A floating body's vertical velocity after the contact (step 4): the common velocity, then gravity.
POND_BODY_FN float contact_fall(float common_v, float gravity_dt) {
  POND_PRECISE float vy = common_v - gravity_dt;
  return vy;
}

// Whether a node at height y is strictly inside the chord.
POND_BODY_FN bool contact_inside(float y, float by, float half_height) {
  POND_PRECISE float dy = y - by;
  return dy < half_height && -dy < half_height;
}

// The common velocity of a floating body (velocity vb, k = node mass / body mass) and n nodes
// whose velocities sum to `sum`: (vb + k sum) / (1 + n k). The division is the exact rsqrt
// squared, so every backend rounds it alike.
POND_BODY_FN float contact_common_velocity(float vb, float sum, uint n, float k) {
  POND_PRECISE float momentum = vb + k * sum;
  POND_PRECISE float mass = 1.0f + float(n) * k;
  POND_PRECISE float r = rsqrt_exact(mass, kRsqrtStepsExact);
  POND_PRECISE float inv_mass = r * r;
  POND_PRECISE float common_v = momentum * inv_mass;
  return common_v;
}

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#undef POND_BODY_FN
#endif
