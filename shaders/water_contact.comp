#version 460
// The bodies' contact after one substep (the algorithm and its order: shared/bodies.h), in one
// workgroup that takes the bodies one after the other: all invocations move the body alike; lane
// l = (i % 8) * 8 + j % 8 of the POND_CONTACT_LANES lanes tests its footprint nodes (i, j) in
// row-major order and keeps its own sums; every invocation adds the lanes' sums in lane order;
// then the lanes move their nodes inside to the surface with the common velocity. A barrier
// separates the bodies, so a body sees the nodes the one before it moved. Every float operation
// is `precise` (the CPU's bits).
//
// The workgroup has local_size_x invocations (a specialization constant dividing the 64 lanes: the
// device's subgroup size, so that llvmpipe runs it as one SIMD batch without switching between
// batches at each barrier); invocation t takes lanes t, t + local_size_x, ... The lanes and their
// order are the same for any size: the same bits.
//
// A node is loaded only as far as needed: its rest position decides whether it can touch the body
// (contact_may_touch, no load), then ux and uz whether it is under the sphere, and only then its
// kind and height (on llvmpipe every storage-buffer load with a per-invocation address is a loop
// over the lanes).
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

// uy and vy, which an earlier body of the same pass may have moved, through the coherent storage
// buffer; ux, uz and the kinds, which this pass never writes, through texel-buffer views (a
// straight-line gather on llvmpipe; see water_step.comp). The state's view aliases `state` (on
// components it does not write), so `state` is not `restrict`.
layout(std430, set = 0, binding = POND_CONTACT_BINDING_STATE) coherent buffer State { float state[]; };
layout(set = 0, binding = POND_CONTACT_BINDING_STATE1) uniform samplerBuffer state1;  // R32F: float n
layout(set = 0, binding = POND_CONTACT_BINDING_KINDS4) uniform usamplerBuffer kinds4;  // RGBA8UI: nodes 4t..4t+3
layout(std430, set = 0, binding = POND_CONTACT_BINDING_BODIES) coherent restrict buffer Bodies { BodyState bodies[]; };
layout(std430, set = 0, binding = POND_CONTACT_BINDING_CONSTANTS) restrict readonly buffer Constants {
  BodyConstants constants[];
};
layout(std430, set = 0, binding = POND_CONTACT_BINDING_SCHEDULE) restrict readonly buffer Schedule {
  BodyState schedule[];
};
layout(std430, set = 0, binding = POND_CONTACT_BINDING_REACH) coherent restrict buffer Reach { uint reach_bits; };
layout(push_constant) uniform Push { ContactPush p; };

shared float lane_sums[POND_CONTACT_LANES];
shared uint lane_counts[POND_CONTACT_LANES];
// A floating body's pass 1 keeps each lane's first kCacheDepth nodes inside (index, height on the
// surface) for pass 2, at slot lane + LANES * m: pass 2 then only writes them, where it would load
// and test the footprint again. A lane with more nodes inside (a large body) walks it again.
const uint kCacheDepth = 16u;
shared uint cached_node[POND_CONTACT_LANES * kCacheDepth];
shared float cached_height[POND_CONTACT_LANES * kCacheDepth];

const uint kY = 1u, kVy = 4u;  // component arrays of the state (water_gpu.h)

// Whether footprint node (i, j) (state index n) is inside the body: not fixed, under the sphere
// (half chord `half_height` over its actual x, z) and within that chord at its height `y`.
bool inside_at(int i, int j, BodyState b, float r2, out uint n, out float half_height, out float y) {
  n = uint(i) * p.pitch + uint(j);
  precise float x = float(j) + texelFetch(state1, int(n)).x;                 // ux
  precise float z = float(i) + texelFetch(state1, int(2u * p.stride + n)).x;  // uz
  half_height = contact_half_height(x, z, b.x, b.z, r2);
  y = 0.0;
  if (!(half_height > 0.0)) return false;
  const uint kind = texelFetch(kinds4, int(n >> 2u))[n & 3u];
  if (kind == kNodeFixed) return false;
  y = state[kY * p.stride + n];
  return contact_inside(y, b.y, half_height);
}

// The first index from `first` on that is congruent to `residue` modulo the lane side.
int first_of_lane(int first, int residue) {
  return first + ((residue - (first % POND_CONTACT_LANE_SIDE) + POND_CONTACT_LANE_SIDE) % POND_CONTACT_LANE_SIDE);
}

// Buffer structs copied member by member (a whole-struct copy between layouts is not valid SPIR-V).
BodyState body_at(uint index) {
  return BodyState(bodies[index].x, bodies[index].y, bodies[index].z, bodies[index].vx, bodies[index].vy,
                   bodies[index].vz);
}
BodyState scheduled_at(uint entry) {
  return BodyState(schedule[entry].x, schedule[entry].y, schedule[entry].z, schedule[entry].vx, schedule[entry].vy,
                   schedule[entry].vz);
}

void main() {
  const uint first_lane = gl_LocalInvocationID.x, invocations = gl_WorkGroupSize.x;
  const float reach = uintBitsToFloat(reach_bits);  // the step shader's, for this substep
  for (uint index = 0u; index < p.count; ++index) {
    const BodyConstants c = BodyConstants(constants[index].radius, constants[index].radius2,
                                          constants[index].node_over_body, constants[index].gravity_dt,
                                          constants[index].floating);
    BodyState b = c.floating != 0u ? contact_move_floating(body_at(index), p.dt, p.rim_x, p.rim_z)
                                   : scheduled_at(p.schedule_first + index);
    const float extent = contact_extent(c.radius, reach), limit2 = contact_touch_limit2(c.radius);
    const int i0 = footprint_first(b.z, extent), i1 = footprint_last(b.z, extent, int(p.rows) - 1);
    const int j0 = footprint_first(b.x, extent), j1 = footprint_last(b.x, extent, int(p.cols) - 1);
    float common_v = b.vy;
    if (c.floating != 0u) {
      for (uint lane = first_lane; lane < POND_CONTACT_LANES; lane += invocations) {
        precise float sum = 0.0;
        uint nodes = 0u;
        const int lane_i = int(lane) / POND_CONTACT_LANE_SIDE, lane_j = int(lane) % POND_CONTACT_LANE_SIDE;
        for (int i = first_of_lane(i0, lane_i); i <= i1; i += POND_CONTACT_LANE_SIDE)
          for (int j = first_of_lane(j0, lane_j); j <= j1; j += POND_CONTACT_LANE_SIDE) {
            if (!contact_may_touch(j, i, b.x, b.z, reach, limit2)) continue;
            uint n;
            float half_height, y;
            if (inside_at(i, j, b, c.radius2, n, half_height, y)) {
              sum = sum + state[kVy * p.stride + n];
              if (nodes < kCacheDepth) {
                cached_node[lane + POND_CONTACT_LANES * nodes] = n;
                cached_height[lane + POND_CONTACT_LANES * nodes] = contact_surface(y, b.y, half_height);
              }
              ++nodes;
            }
          }
        lane_sums[lane] = sum;
        lane_counts[lane] = nodes;
      }
      barrier();  // also orders the shared-memory writes (compute shaders)
      precise float total = 0.0;
      uint all_nodes = 0u;
      for (uint l = 0u; l < POND_CONTACT_LANES; ++l) {
        total = total + lane_sums[l];
        all_nodes += lane_counts[l];
      }
      if (all_nodes > 0u) common_v = contact_common_velocity(b.vy, total, all_nodes, c.node_over_body);
      b.vy = contact_fall(common_v, c.gravity_dt);
    }
    for (uint lane = first_lane; lane < POND_CONTACT_LANES; lane += invocations) {
      if (c.floating != 0u && lane_counts[lane] <= kCacheDepth) {  // pass 1 kept all of this lane's
        for (uint m = 0u; m < lane_counts[lane]; ++m) {
          const uint n = cached_node[lane + POND_CONTACT_LANES * m];
          state[kY * p.stride + n] = cached_height[lane + POND_CONTACT_LANES * m];
          state[kVy * p.stride + n] = common_v;
        }
        continue;
      }
      const int lane_i = int(lane) / POND_CONTACT_LANE_SIDE, lane_j = int(lane) % POND_CONTACT_LANE_SIDE;
      for (int i = first_of_lane(i0, lane_i); i <= i1; i += POND_CONTACT_LANE_SIDE)
        for (int j = first_of_lane(j0, lane_j); j <= j1; j += POND_CONTACT_LANE_SIDE) {
          if (!contact_may_touch(j, i, b.x, b.z, reach, limit2)) continue;
          uint n;
          float half_height, y;
          if (inside_at(i, j, b, c.radius2, n, half_height, y)) {
            state[kY * p.stride + n] = contact_surface(y, b.y, half_height);
            state[kVy * p.stride + n] = common_v;
          }
        }
    }
    // Every lane read bodies[index] and the lane sums above; the next body sees these nodes.
    memoryBarrierBuffer();
    barrier();
    if (first_lane == 0u) {
      bodies[index].x = b.x;
      bodies[index].y = b.y;
      bodies[index].z = b.z;
      bodies[index].vx = b.vx;
      bodies[index].vy = b.vy;
      bodies[index].vz = b.vz;
    }
  }
  barrier();  // every invocation has read the reach: the next substep's step shader starts from 0
  if (first_lane == 0u) reach_bits = 0u;
}
