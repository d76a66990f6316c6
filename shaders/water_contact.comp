#version 460
// The bodies' contact after one substep (the algorithm and its order: shared/bodies.h), in one
// workgroup that takes the bodies one after the other: all invocations move the body alike; lane l
// of the POND_CONTACT_LANES lanes tests the footprint nodes k = l, l + LANES, ... and keeps its own
// sums; every invocation adds the lanes' sums in lane order; then the lanes move their nodes inside
// to the surface with the common velocity. A barrier separates the bodies, so a body sees the
// nodes the one before it moved. Every float operation is `precise` (the CPU's bits).
//
// The workgroup has local_size_x invocations (a specialization constant dividing the 64 lanes: the
// device's subgroup size, so that llvmpipe runs it as one SIMD batch without switching between
// batches at each barrier); invocation t takes lanes t, t + local_size_x, ... The lanes and their
// order are the same for any size: the same bits.
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

layout(std430, set = 0, binding = POND_CONTACT_BINDING_STATE) coherent restrict buffer State { float state[]; };
layout(std430, set = 0, binding = POND_CONTACT_BINDING_KINDS) restrict readonly buffer Kinds { uint kinds[]; };
layout(std430, set = 0, binding = POND_CONTACT_BINDING_BODIES) coherent restrict buffer Bodies { BodyState bodies[]; };
layout(std430, set = 0, binding = POND_CONTACT_BINDING_CONSTANTS) restrict readonly buffer Constants {
  BodyConstants constants[];
};
layout(std430, set = 0, binding = POND_CONTACT_BINDING_SCHEDULE) restrict readonly buffer Schedule {
  BodyState schedule[];
};
layout(push_constant) uniform Push { ContactPush p; };

shared float lane_sums[POND_CONTACT_LANES];
shared uint lane_counts[POND_CONTACT_LANES];

const uint kY = 1u, kVy = 4u;  // component arrays of the state (water_gpu.h)

// Footprint node (i, j): its state index, and the half chord over it (0: fixed, or outside the
// sphere).
float half_height_at(int i, int j, BodyState b, float r2, out uint n) {
  n = uint(i) * p.pitch + uint(j);
  const uint kind = (kinds[n >> 2u] >> (8u * (n & 3u))) & 0xffu;
  if (kind == kNodeFixed) return 0.0;
  precise float x = float(j) + state[n];                 // ux
  precise float z = float(i) + state[2u * p.stride + n];  // uz
  return contact_half_height(x, z, b.x, b.z, r2);
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

// A lane's walk over the footprint: node k = lane, lane + LANES, ... (row-major, `width` columns
// from (i0, j0)) without a division per node.
struct Walk {
  int i, j;    // the current node
  int di, dj;  // LANES nodes further on: di rows and dj columns (then one row more past the edge)
};
Walk walk_start(uint lane, int i0, int j0, uint width) {
  return Walk(i0 + int(lane / width), j0 + int(lane % width), int(POND_CONTACT_LANES / width),
              int(POND_CONTACT_LANES % width));
}
void walk_next(inout Walk w, int j0, uint width) {
  w.i += w.di;
  w.j += w.dj;
  if (w.j >= j0 + int(width)) {
    w.j -= int(width);
    ++w.i;
  }
}

void main() {
  const uint first_lane = gl_LocalInvocationID.x, invocations = gl_WorkGroupSize.x;
  for (uint index = 0u; index < p.count; ++index) {
    const BodyConstants c = BodyConstants(constants[index].radius, constants[index].radius2,
                                          constants[index].node_over_body, constants[index].gravity_dt,
                                          constants[index].floating);
    BodyState b = c.floating != 0u ? contact_move_floating(body_at(index), p.dt, p.rim_x, p.rim_z)
                                   : scheduled_at(p.schedule_first + index);
    const int i0 = footprint_first(b.z, c.radius), i1 = footprint_last(b.z, c.radius, int(p.rows) - 1);
    const int j0 = footprint_first(b.x, c.radius), j1 = footprint_last(b.x, c.radius, int(p.cols) - 1);
    const uint width = j1 >= j0 ? uint(j1 - j0 + 1) : 0u;
    const uint count = i1 >= i0 ? width * uint(i1 - i0 + 1) : 0u;
    float common_v = b.vy;
    if (c.floating != 0u) {
      for (uint lane = first_lane; lane < POND_CONTACT_LANES; lane += invocations) {
        precise float sum = 0.0;
        uint nodes = 0u;
        Walk w = walk_start(lane, i0, j0, max(width, 1u));
        for (uint k = lane; k < count; k += POND_CONTACT_LANES) {
          uint n;
          const float half_height = half_height_at(w.i, w.j, b, c.radius2, n);
          if (half_height > 0.0 && contact_inside(state[kY * p.stride + n], b.y, half_height)) {
            sum = sum + state[kVy * p.stride + n];
            ++nodes;
          }
          walk_next(w, j0, width);
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
      Walk w = walk_start(lane, i0, j0, max(width, 1u));
      for (uint k = lane; k < count; k += POND_CONTACT_LANES) {
        uint n;
        const float half_height = half_height_at(w.i, w.j, b, c.radius2, n);
        const float y = state[kY * p.stride + n];
        if (half_height > 0.0 && contact_inside(y, b.y, half_height)) {
          state[kY * p.stride + n] = contact_surface(y, b.y, half_height);
          state[kVy * p.stride + n] = common_v;
        }
        walk_next(w, j0, width);
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
}
