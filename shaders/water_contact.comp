#version 460
// The bodies' contact after one substep (the order: shared/bodies.h; the laws: shared/body_*.h),
// in one workgroup that holds the bodies in shared memory:
//  1. the floating bodies' exchanges with the water, each by one invocation, in rounds: a body
//     waits for the bodies before it whose kernels overlap its own, so every node sees the bodies
//     over it in scene order; the moments are summed in the CPU's lane order (body_water.h);
//  2. the motion: the bodies' moves in parallel; each pass's candidate pairs found in parallel and
//     resolved on invocation 0 in index order (the order is the law); the land in parallel (each
//     body alone against it);
//  3. kinematic bodies one after the other: the lanes push the nodes inside to the surface.
// Every float operation is `precise` (the CPU's bits). The workgroup has local_size_x invocations
// (a specialization constant dividing the 64 lanes: the device's subgroup size, so that llvmpipe
// runs it as one SIMD batch); in step 3 invocation t takes lanes t, t + local_size_x, ...: the same
// lanes, and so the same bits, for any size.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require

#include "shared/exact_math.h"
#include "shared/water_gpu.h"
#include "shared/bodies.h"

spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve, 32-bit floats
#ifdef POND_DENORM_PRESERVE  // the variant for devices with shaderDenormPreserveFloat32 (float_policy.h)
spirv_execution_mode(capabilities = [4464], 4459, 32);  // DenormPreserve, 32-bit floats
#endif

layout(local_size_x = POND_CONTACT_LOCAL_X, local_size_y = 1, local_size_z = 1) in;
layout(local_size_x_id = POND_SPEC_CONTACT_LOCAL_X) in;

// uy and the velocities, which this pass writes, through the coherent storage buffer; ux, uz and
// the kinds, which it never writes, through texel-buffer views (a straight-line gather on
// llvmpipe). The state's view aliases `state` (on components it does not write), so `state` is
// not `restrict`.
layout(std430, set = 0, binding = POND_CONTACT_BINDING_STATE) coherent buffer State { float state[]; };
layout(set = 0, binding = POND_CONTACT_BINDING_STATE1) uniform samplerBuffer state1;  // R32F: float n
layout(set = 0, binding = POND_CONTACT_BINDING_KINDS4) uniform usamplerBuffer kinds4;  // RGBA8UI: nodes 4t..4t+3
layout(std430, set = 0, binding = POND_CONTACT_BINDING_BODIES) restrict buffer Bodies { BodyState bodies[]; };
layout(std430, set = 0, binding = POND_CONTACT_BINDING_CONSTANTS) restrict readonly buffer Constants {
  BodyConstants constants[];
};
layout(std430, set = 0, binding = POND_CONTACT_BINDING_SCHEDULE) restrict readonly buffer Schedule {
  BodyState schedule[];
};
layout(std430, set = 0, binding = POND_CONTACT_BINDING_REACH) coherent restrict buffer Reach { uint reach_bits; };
layout(std430, set = 0, binding = POND_CONTACT_BINDING_LAND) restrict readonly buffer Land { uint land[]; };
layout(push_constant) uniform Push { ContactPush p; };

// The bodies (sb), their constants (sc) and the kinematic ones' positions at the substep's end
// (sk): the arrays shared/body_motion.h and body_pairs.h work on.
shared BodyState sb[POND_MAX_BODIES];
shared BodyConstants sc[POND_MAX_BODIES];
shared BodyState sk[POND_MAX_BODIES];
shared float moves[POND_MAX_BODIES];
shared uint pairs_touched;
shared PairMask pairs[POND_MAX_BODIES];  // this pass's pairs that may touch (body_pairs.h)

#include "shared/body_kinematic.h"
#include "shared/body_motion.h"
#include "shared/body_pairs.h"
#include "shared/body_water.h"

// Step 1's schedule: each body's kernel (rows x..y, columns z..w), the bodies it waits for (bit a:
// body a), whether it has exchanged, and whether it does in this round.
shared ivec4 boxes[POND_MAX_BODIES];
shared uvec2 waits[POND_MAX_BODIES];
shared uint exchanged[POND_MAX_BODIES];
shared uint ready[POND_MAX_BODIES];

const uint kY = 1u, kVx = 3u, kVy = 4u, kVz = 5u;  // component arrays of the state (water_gpu.h)

uint kind_at(uint n) { return texelFetch(kinds4, int(n >> 2u))[n & 3u]; }

// The first index from `first` on that is congruent to `residue` modulo the lane side (a
// power of two: a mask, not an integer division, which a CPU device runs lane by lane).
int first_of_lane(int first, int residue) {
  const int mask = POND_CONTACT_LANE_SIDE - 1;
  return first + ((residue - first) & mask);
}

// Buffer structs copied member by member (a whole-struct copy between layouts is not valid SPIR-V).
BodyState body_at(uint index) {
  return BodyState(bodies[index].x, bodies[index].y, bodies[index].z, bodies[index].vx, bodies[index].vy,
                   bodies[index].vz, bodies[index].flags);
}
BodyState scheduled_at(uint entry) {
  return BodyState(schedule[entry].x, schedule[entry].y, schedule[entry].z, schedule[entry].vx, schedule[entry].vy,
                   schedule[entry].vz, schedule[entry].flags);
}
BodyConstants constants_at(uint index) {
  return BodyConstants(constants[index].radius, constants[index].radius2, constants[index].inv_radius,
                       constants[index].inv_4r3, constants[index].node_over_body, constants[index].body_over_node,
                       constants[index].inv_mass, constants[index].gravity_dt, constants[index].buoyancy_dt,
                       constants[index].drag_dt, constants[index].floating);
}

// Step 1's kernel of body `index`: its first and last row (x, y) and column (z, w).
ivec4 kernel_box(uint index) {
  const BodyState b = sb[index];
  const float r = sc[index].radius;
  const int last_i = int(p.rows) - 1, last_j = int(p.cols) - 1;
  return ivec4(water_first(b.z, r, last_i), water_last(b.z, r, last_i), water_first(b.x, r, last_j),
               water_last(b.x, r, last_j));
}

bool boxes_overlap(ivec4 a, ivec4 b) { return a.x <= b.y && b.x <= a.y && a.z <= b.w && b.z <= a.w; }

// The index, among `count` consecutive ones from `first`, where the t-th residue class modulo the
// lane side present among them starts, in ascending residue order.
int lane_start(int first, int count, int t) {
  const int mask = POND_CONTACT_LANE_SIDE - 1;
  if (count >= POND_CONTACT_LANE_SIDE) return first + ((t - first) & mask);
  const int wrap = (-first) & mask, u = t + wrap;  // residue 0 is at first + wrap, if present
  return first + (u < count ? u : (wrap < count ? u - count : t));
}

// The moments of the water under body b (constants c, kernel box k), reduced as the CPU does: lane
// by lane in lane order, each lane's nodes row-major. Only the lanes the box covers are visited: an
// empty lane would add +0, which changes no sum (a sum of these moments is never -0).
WaterMoments kernel_moments(BodyState b, BodyConstants c, ivec4 k) {
  WaterMoments total = moments_zero();
  const int rows = k.y - k.x + 1, cols = k.w - k.z + 1;
  const int row_lanes = min(rows, POND_CONTACT_LANE_SIDE), col_lanes = min(cols, POND_CONTACT_LANE_SIDE);
  for (int lane_i = 0; lane_i < row_lanes; ++lane_i) {
    const int first_i = lane_start(k.x, rows, lane_i);
    for (int lane_j = 0; lane_j < col_lanes; ++lane_j) {
      const int first_j = lane_start(k.z, cols, lane_j);
      WaterMoments m = moments_zero();
      for (int i = first_i; i <= k.y; i += POND_CONTACT_LANE_SIDE)
        for (int j = first_j; j <= k.w; j += POND_CONTACT_LANE_SIDE) {
          const float w = water_weight(j, i, b.x, b.z, c.inv_radius);
          if (!(w > 0.0)) continue;
          const uint n = uint(i) * p.pitch + uint(j), kind = kind_at(n);
          if (kind == kNodeFixed) continue;
          m = moments_add_node(m, w, j, i, b.x, b.z, state[kY * p.stride + n], state[kVx * p.stride + n],
                               state[kVy * p.stride + n], state[kVz * p.stride + n], kind == kNodeFree);
        }
      total = moments_add(total, m);
    }
  }
  return total;
}

// The nodes under body b take the exchange's kicks (each node once: any order).
void kick_kernel(BodyState b, BodyConstants c, ivec4 k, WaterExchange e) {
  for (int i = k.x; i <= k.y; ++i)
    for (int j = k.z; j <= k.w; ++j) {
      const float w = water_weight(j, i, b.x, b.z, c.inv_radius);
      if (!(w > 0.0)) continue;
      const uint n = uint(i) * p.pitch + uint(j), kind = kind_at(n);
      if (kind == kNodeFixed) continue;
      state[kVy * p.stride + n] = water_kick(state[kVy * p.stride + n], e.cy, w);
      if (kind != kNodeFree) continue;
      state[kVx * p.stride + n] = water_kick(state[kVx * p.stride + n], e.cx, w);
      state[kVz * p.stride + n] = water_kick(state[kVz * p.stride + n], e.cz, w);
    }
}

// Whether every body in `bodies` (bit a: body a) has exchanged.
bool all_exchanged(uvec2 bodies) {
  for (uint word = 0u; word < 2u; ++word)
    for (uint bits = bodies[word]; bits != 0u; bits &= bits - 1u)
      if (exchanged[32u * word + uint(findLSB(bits))] == 0u) return false;
  return true;
}

// Step 1: the floating bodies' exchanges, each by one invocation, in rounds. Body b waits for the
// floating bodies before it whose kernels overlap its own; bodies with disjoint kernels read and
// write disjoint nodes, so any order that keeps the waits gives the bits of scene order.
void exchange_with_water(uint first, uint invocations) {
  uint floating = 0u;
  for (uint i = 0u; i < p.count; ++i) floating += sc[i].floating;
  for (uint i = first; i < p.count; i += invocations) {
    boxes[i] = kernel_box(i);
    exchanged[i] = 0u;
  }
  barrier();
  for (uint i = first; i < p.count; i += invocations) {
    uvec2 before = uvec2(0u);
    for (uint a = 0u; a < i; ++a)
      if (sc[a].floating != 0u && boxes_overlap(boxes[a], boxes[i])) before[a >> 5u] |= 1u << (a & 31u);
    waits[i] = before;
  }
  barrier();
  for (uint done = 0u; done < floating;) {
    for (uint i = first; i < p.count; i += invocations) {
      ready[i] = sc[i].floating != 0u && exchanged[i] == 0u && all_exchanged(waits[i]) ? 1u : 0u;
      if (ready[i] == 0u) continue;
      const BodyState b = sb[i];
      const BodyConstants c = sc[i];
      const WaterExchange e = water_exchange(kernel_moments(b, c, boxes[i]), b, c);
      if (e.wet != 0u) kick_kernel(b, c, boxes[i], e);
      sb[i] = e.body;
    }
    memoryBarrierBuffer();
    barrier();  // the next round sees these nodes
    for (uint i = first; i < p.count; i += invocations)
      if (ready[i] != 0u) exchanged[i] = 1u;
    barrier();
    done = 0u;
    for (uint i = 0u; i < p.count; ++i) done += exchanged[i];
    barrier();  // every invocation has counted before the next round marks
  }
}

// One sub-iteration's time step: dt / n (a helper of its own: glslang's `precise` propagation
// takes exponential time over move_bodies()'s loops).
float sub_iteration_dt(int n) {
  precise float dt_n = p.dt * inv_exact(float(n));
  return dt_n;
}

// Node n's (row i, column j) half chord under a sphere centred at (bx, bz) of squared radius r2,
// from the node's actual x and z (a helper for the same reason).
float node_half_height(uint n, int i, int j, float bx, float bz, float r2) {
  precise float x = float(j) + texelFetch(state1, int(n)).x;                 // ux
  precise float z = float(i) + texelFetch(state1, int(2u * p.stride + n)).x;  // uz
  return contact_half_height(x, z, bx, bz, r2);
}

// Step 2: every body through the substep, in sub-iterations (shared/body_motion.h).
void move_bodies(uint first, uint invocations) {
  for (uint i = first; i < p.count; i += invocations) moves[i] = body_prepare(sb[i], sc[i], sk[i], p.max_speed, p.dt);
  barrier();
  float most = 0.0;
  for (uint i = 0u; i < p.count; ++i) most = moves[i] > most ? moves[i] : most;
  const int n = motion_iterations(most);
  const float dt_n = sub_iteration_dt(n);
  for (int it = 0; it < n; ++it) {
    for (uint i = first; i < p.count; i += invocations) sb[i] = body_advance(sb[i], sc[i], sk[i], dt_n, n - it);
    barrier();
    for (int pass = 0; pass < POND_PAIR_PASSES; ++pass) {
      for (uint a = first; a < p.count; a += invocations) pairs[a] = pair_candidates(a, p.count);
      barrier();
      if (first == 0u) pairs_touched = resolve_pairs(p.count, p.bounce_speed) ? 1u : 0u;
      barrier();
      for (uint i = first; i < p.count; i += invocations)
        if (sc[i].floating != 0u) collide_land(sb[i], sc[i], p);
      barrier();
      const bool again = pairs_touched != 0u;
      barrier();  // every invocation has read pairs_touched before the next pass writes it
      if (!again) break;
    }
  }
}

// Step 3 for kinematic body `index`: the nodes inside it to its surface, with its vertical velocity.
void push_out(uint index, uint first_lane, uint invocations, float reach) {
  const BodyState b = sb[index];
  const BodyConstants c = sc[index];
  const float extent = contact_extent(c.radius, reach), limit2 = contact_touch_limit2(c.radius);
  const int i0 = footprint_first(b.z, extent), i1 = footprint_last(b.z, extent, int(p.rows) - 1);
  const int j0 = footprint_first(b.x, extent), j1 = footprint_last(b.x, extent, int(p.cols) - 1);
  for (uint lane = first_lane; lane < POND_CONTACT_LANES; lane += invocations) {
    const int lane_i = int(lane) / POND_CONTACT_LANE_SIDE, lane_j = int(lane) % POND_CONTACT_LANE_SIDE;
    for (int i = first_of_lane(i0, lane_i); i <= i1; i += POND_CONTACT_LANE_SIDE)
      for (int j = first_of_lane(j0, lane_j); j <= j1; j += POND_CONTACT_LANE_SIDE) {
        if (!contact_may_touch(j, i, b.x, b.z, reach, limit2)) continue;
        const uint n = uint(i) * p.pitch + uint(j);
        const float half_height = node_half_height(n, i, j, b.x, b.z, c.radius2);
        if (!(half_height > 0.0) || kind_at(n) == kNodeFixed) continue;
        const float y = state[kY * p.stride + n];
        if (!contact_inside(y, b.y, half_height)) continue;
        state[kY * p.stride + n] = contact_surface(y, b.y, half_height);
        state[kVy * p.stride + n] = b.vy;
      }
  }
  memoryBarrierBuffer();
  barrier();  // the next body sees these nodes
}

void main() {
  const uint first = gl_LocalInvocationID.x, invocations = gl_WorkGroupSize.x;
  const float reach = uintBitsToFloat(reach_bits);  // the step shader's, for this substep
  for (uint i = first; i < p.count; i += invocations) {
    sb[i] = body_at(i);
    sc[i] = constants_at(i);
    sk[i] = sc[i].floating != 0u ? sb[i] : scheduled_at(p.schedule_first + i);
  }
  barrier();
  exchange_with_water(first, invocations);
  move_bodies(first, invocations);
  for (uint index = 0u; index < p.count; ++index)
    if (sc[index].floating == 0u) push_out(index, first, invocations, reach);
  for (uint i = first; i < p.count; i += invocations) {
    sb[i] = canonical_body(sb[i]);
    bodies[i].x = sb[i].x;
    bodies[i].y = sb[i].y;
    bodies[i].z = sb[i].z;
    bodies[i].vx = sb[i].vx;
    bodies[i].vy = sb[i].vy;
    bodies[i].vz = sb[i].vz;
    bodies[i].flags = sb[i].flags;
  }
  barrier();  // every invocation has read the reach: the next substep's step shader starts from 0
  if (first == 0u) reach_bits = 0u;
}
