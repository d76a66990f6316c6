#version 460
// Packs runs of nodes of the state's displacements (ux | uy | uz) for the host to read back, where
// it holds only what the LOD reads (gpu/displacement_readback.h): one workgroup per run and
// component at a time, its invocations along the run. Bit copies of 32-bit words: no float
// arithmetic, so every device gives the state's own bits. One dispatch however many runs, where
// a copy command would take one region per run.
#extension GL_GOOGLE_include_directive : require

#include "shared/water_gpu.h"

layout(local_size_x = POND_GATHER_LOCAL_X, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = POND_GATHER_BINDING_STATE) restrict readonly buffer State { uint state[]; };
layout(std430, set = 0, binding = POND_GATHER_BINDING_RUNS) restrict readonly buffer Runs { GatherRun runs[]; };
layout(std430, set = 0, binding = POND_GATHER_BINDING_PACKED) restrict writeonly buffer Packed { uint packed[]; };
layout(push_constant) uniform Push { GatherPush p; };

void main() {
  const uint c = gl_WorkGroupID.y;  // the component
  for (uint r = gl_WorkGroupID.x; r < p.runs; r += gl_NumWorkGroups.x) {
    const GatherRun run = runs[r];
    for (uint k = gl_LocalInvocationID.x; k < run.nodes; k += uint(POND_GATHER_LOCAL_X))
      packed[c * p.run_nodes + run.packed + k] = state[c * p.stride + run.first + k];
  }
}
