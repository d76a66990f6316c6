#version 460
// Vertex normals of a state into the buffer the water vertex shader reads (one vec4 per node):
//   n = normalize((x[i+1][j] - x[i-1][j]) x (x[i][j+1] - x[i][j-1])),
// central differences, one-sided at the border, +y at rest. The same operations in the same order
// as sim::compute_normals (src/sim/normals.cpp), all `precise`, normalized with the exact Newton
// rsqrt, so the GPU normals equal the CPU's bit for bit.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require

#include "shared/exact_math.h"
#include "shared/water_gpu.h"

spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve, 32-bit floats

layout(local_size_x = POND_NORMALS_LOCAL_X, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = 0) restrict readonly buffer State { float state[]; };
layout(std430, set = 0, binding = 1) restrict writeonly buffer Normals { vec4 normals[]; };
layout(push_constant) uniform Push { NormalsPush p; };

vec3 load_u(uint n) { return vec3(state[n], state[p.stride + n], state[2u * p.stride + n]); }

void main() {
  const uint n = gl_GlobalInvocationID.x;
  if (n >= p.rows * p.cols) return;
  const uint i = n / p.cols, j = n % p.cols;
  const uint i1 = min(i + 1u, p.rows - 1u), i0 = i > 0u ? i - 1u : 0u;
  const uint j1 = min(j + 1u, p.cols - 1u), j0 = j > 0u ? j - 1u : 0u;
  // Position differences = displacement differences + the rest offset (i1 - i0 or j1 - j0),
  // added even when it is 0, as the CPU does.
  precise vec3 a = load_u(i1 * p.cols + j) - load_u(i0 * p.cols + j);
  a.z = a.z + float(i1 - i0);
  precise vec3 b = load_u(i * p.cols + j1) - load_u(i * p.cols + j0);
  b.x = b.x + float(j1 - j0);
  precise float cx = a.y * b.z - a.z * b.y;
  precise float cy = a.z * b.x - a.x * b.z;
  precise float cz = a.x * b.y - a.y * b.x;
  precise float l2 = (cx * cx + cy * cy) + cz * cz;
  const bool ok = l2 > 0.0;
  precise float r = ok ? rsqrt_exact(l2, kRsqrtStepsExact) : 0.0;
  precise vec3 nrm = vec3(cx * r, ok ? cy * r : 1.0, cz * r);
  normals[n] = vec4(nrm, 0.0);
}
