#version 460
// One tabulated perturbation (sim::PerturbationTable): for entries [first, first + count) of the
// table buffer, w is added to (add) or written into (set) the y velocity or y position of the node.
// The weights were computed on the CPU (exp is not exact on GPUs); the one addition is `precise`.
// A table lists each node at most once, so invocations never race. Node indices are the state's
// (row * pitch + col, shared/water_gpu.h): the solver converts the model's tables when it uploads them.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require

#include "shared/exact_math.h"
#include "shared/water_gpu.h"

spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve, 32-bit floats
#ifdef POND_DENORM_PRESERVE  // the variant for devices with shaderDenormPreserveFloat32 (float_policy.h)
spirv_execution_mode(capabilities = [4464], 4459, 32);  // DenormPreserve, 32-bit floats
#endif

layout(local_size_x = POND_PERTURB_LOCAL_X, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = 0) restrict buffer State { float state[]; };
layout(std430, set = 0, binding = 1) restrict readonly buffer Table { PerturbEntry entries[]; };
layout(push_constant) uniform Push { PerturbPush p; };

void main() {
  const uint k = gl_GlobalInvocationID.x;
  if (k >= p.count) return;
  const PerturbEntry e = entries[p.first + k];
  const uint slot = (p.target == kPerturbVelocity ? 4u : 1u) * p.stride + e.node;  // vy or y
  precise float sum = state[slot] + e.weight;
  state[slot] = p.mode == kPerturbAdd ? sum : e.weight;
}
