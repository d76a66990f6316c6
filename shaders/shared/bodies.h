// The bodies in the water (spheres): their state, constants, the contact pass's bindings and push
// constants, declared once for GLSL (water_contact.comp) and C++ (sim/contact.cpp, the GPU solver).
// The laws are in the headers beside this one, each included by both sides:
//  - body_water.h: a floating body and the water (buoyancy, drag, displacement);
//  - body_motion.h: every body's motion through a substep, in sub-iterations;
//  - body_pairs.h: body against body; body_land.h: a floating body against the walls, the floor
//    and the land;
//  - body_kinematic.h: a kinematic body pushing the nodes out of itself.
//
// One substep's contact, after the water's integration (grid units throughout):
//  1. every floating body in scene order exchanges with the water under it (body_water.h); a body
//     sees the nodes the ones before it changed;
//  2. every body moves (floating by its velocity, kinematic along its path) in sub-iterations short
//     enough that nothing is crossed, resolving body against body in one fixed pair order, then
//     each floating body against the land (body_pairs.h, body_land.h);
//  3. every kinematic body in scene order pushes the nodes inside it to its surface
//     (body_kinematic.h).
#ifndef POND_BODIES_H
#define POND_BODIES_H

#include "shared/exact_math.h"

#define POND_MAX_BODIES 64        // a scene's bodies at most (the contact pass keeps them in shared memory)
#define POND_CONTACT_LANES 64     // the reductions' lanes (partial sums), whatever the invocations
#define POND_CONTACT_LANE_SIDE 8  // lane of node (i, j): (i % 8) * 8 + j % 8
#define POND_CONTACT_LOCAL_X 64   // default invocations of water_contact.comp; the solver sets it
#define POND_SPEC_CONTACT_LOCAL_X 0  // specialization constant: water_contact.comp's local_size_x

// Bindings of water_contact.comp.
#define POND_CONTACT_BINDING_STATE 0      // storage buffer: the current state, float[] (water_gpu.h)
#define POND_CONTACT_BINDING_KINDS4 1     // uniform texel buffer, R8G8B8A8_UINT view of the kinds (nodes 4t..4t+3)
#define POND_CONTACT_BINDING_BODIES 2     // storage buffer: BodyState[], one per body
#define POND_CONTACT_BINDING_CONSTANTS 3  // storage buffer: BodyConstants[], one per body
#define POND_CONTACT_BINDING_SCHEDULE 4   // storage buffer: BodyState[], kinematic bodies per substep
#define POND_CONTACT_BINDING_REACH 5      // storage buffer: uint, the reach's float bits (water_step.comp)
#define POND_CONTACT_BINDING_STATE1 6     // uniform texel buffer, R32_SFLOAT view of the current state
#define POND_CONTACT_BINDING_LAND 7       // storage buffer: uint[], the land's row runs (below)
#define POND_CONTACT_BINDINGS 8

// The land the bodies meet (body_land.h), as runs of land cells per row of cells, built once per
// model on the CPU (sim/basin.h): word 0 is the number of cell rows R (rows - 1); words 1 .. R + 1
// are where each cell row's runs start and end (row i: runs k in [land[1 + i], land[2 + i])); run k
// is the pair (first column, last column + 1) at words R + 2 + 2k and R + 3 + 2k, in column order.
#define POND_LAND_HEADER(rows_of_cells) (2u + (rows_of_cells))

// Restitution and friction of the contacts (body_land.h, body_pairs.h). A wet ball bounces little
// off sand and stone, more off another ball; below a normal speed of POND_BOUNCE_GRAVITY_SUBSTEPS
// substeps' worth of gravity it does not bounce at all, so that a resting contact stays at rest.
#define POND_RESTITUTION_LAND 0.3f
#define POND_RESTITUTION_BODY 0.5f
#define POND_FRICTION_LAND 0.4f
#define POND_FRICTION_BODY 0.2f
#define POND_BOUNCE_GRAVITY_SUBSTEPS 4.0
// The fastest a body may move: this many grid spacings a step. Faster bodies are refused at load
// and clamped at run time (kBodyClamped).
#define POND_MAX_SPACINGS_PER_STEP 10.0
// Sub-iterations of a substep's motion move no body by more than this (grid units): the smallest
// body (radius 1) and a land cell (1) cannot be crossed.
#define POND_MAX_MOVE_PER_ITERATION 0.5
#define POND_MAX_ITERATIONS 64
// Passes over the pairs of bodies in one sub-iteration at most (a pass in which no pair overlapped
// by more than POND_PAIR_SLOP, body_pairs.h, ends it).
#define POND_PAIR_PASSES 4

#ifdef __cplusplus
#define POND_BODY_CONST inline constexpr
namespace pond::shared {
#else
#define POND_BODY_CONST const
#endif

POND_BODY_CONST int kMaxBodies = POND_MAX_BODIES;
POND_BODY_CONST int kContactLanes = POND_CONTACT_LANES;
POND_BODY_CONST uint kBodyClamped = 1u;  // BodyState::flags: its speed was clamped at least once

// A body's centre and velocity in grid units (world / spacing): the state of one body.
struct BodyState {
  float x, y, z;
  float vx, vy, vz;
  uint flags;  // kBodyClamped, ...: what happened to it so far (the front end says so once)
};

// What does not change while a body moves, rounded once from double on the CPU (sim/bodies.cpp).
struct BodyConstants {
  float radius;
  float radius2;         // radius * radius
  float inv_radius;      // 1 / radius: the water kernel's slope (body_water.h)
  float inv_4r3;         // 1 / (4 radius^3): the submerged fraction of a cap (body_water.h)
  float node_over_body;  // node mass / body mass (0 for a kinematic body)
  float body_over_node;  // body mass / node mass (0 for a kinematic body)
  float inv_mass;        // 1 / body mass (world mass units; 0 for a kinematic body)
  float gravity_dt;      // gravity * dt / spacing: the velocity gravity adds in a substep
  float buoyancy_dt;     // gravity_dt / density: what buoyancy adds in a substep, wholly submerged
  float drag_dt;         // the linear drag's rate * dt, wholly submerged (body_water.h)
  uint floating;         // 1: floating, 0: kinematic
};

// The bodies b > a that body a may touch in a pass of the pairs (body_pairs.h): bit b % 32 of
// words[b / 32].
struct PairMask {
  uint words[2];
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
  float rim_x;          // (cols - 1) and (rows - 1): the pond's walls
  float rim_z;
  float floor_y;        // the pool's floor (-floor_depth / spacing)
  float land_y;         // the top of the land (land_height / spacing)
  float max_speed;      // POND_MAX_SPACINGS_PER_STEP per step, in grid units per time
  float bounce_speed;   // the normal speed below which a contact does not bounce
};

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#undef POND_BODY_CONST

#ifdef __cplusplus
#include <bit>
#include <cmath>
#include <cstdint>
#define POND_BODY_FN inline
#define POND_INOUT(T) T&
namespace pond::shared {
using std::abs;
using std::ceil;
using std::floor;
#else
#define POND_BODY_FN
#define POND_INOUT(T) inout T
#endif

// 1 / x for a normal float x > 0, from the exact reciprocal square root (no division, so every
// backend rounds it alike).
POND_BODY_FN float inv_exact(float x) {
  POND_PRECISE float r = rsqrt_exact(x, kRsqrtStepsExact);
  POND_PRECISE float inv = r * r;
  return inv;
}

// A body's state with every zero made +0 (plus_zero).
POND_BODY_FN BodyState canonical_body(BodyState b) {
  b.x = plus_zero(b.x);
  b.y = plus_zero(b.y);
  b.z = plus_zero(b.z);
  b.vx = plus_zero(b.vx);
  b.vy = plus_zero(b.vy);
  b.vz = plus_zero(b.vz);
  return b;
}

// The reduction lane of node (i, j), both >= 0.
POND_BODY_FN int contact_lane(int i, int j) {
  return (i % POND_CONTACT_LANE_SIDE) * POND_CONTACT_LANE_SIDE + j % POND_CONTACT_LANE_SIDE;
}

// The index of the lowest set bit of bits != 0.
POND_BODY_FN uint lowest_bit(uint bits) {
#ifdef __cplusplus
  return static_cast<uint>(std::countr_zero(bits));
#else
  return uint(findLSB(bits));
#endif
}

// A float index clipped to [0, last] as an int; a non-finite or huge value clips too (a blown-up
// state; the run then stops).
POND_BODY_FN int clip_index(float f, int last) {
  return f > 0.0f ? (f < float(last) ? int(f) : last) : 0;
}

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#endif
