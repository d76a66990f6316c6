#version 460
// One substep of the water grid: spring forces and symplectic Euler, state A -> state B.
//
// Layout and speed (lavapipe/llvmpipe runs 8 invocations per SIMD register and turns every SSBO
// load into a per-lane scalar load, so the number of loads per node decides the speed):
//  - Structure of arrays (shared/water_gpu.h): a node's position is 3 scalar loads, not a vec4.
//  - One invocation per column, walking a strip of POND_STEP_ROWS_PER_INVOCATION rows: the 3x3
//    window of positions slides down, so each node loads its lower row of 3 positions (9 loads)
//    instead of all 9 neighbours (27), and the vertical spring to row i+1 is reused, negated, as
//    the spring to row i-1 of the next node (7 spring evaluations per node instead of 8).
//  - Invocations along x: consecutive lanes read consecutive addresses.
//
// Exact mode (kFastMath false) is bit-identical to the CPU kernel (src/sim/step_kernel.h): every
// operation `precise` (no FMA contraction), the Newton rsqrt of shared/exact_math.h (only + - *),
// the canonical summation order starting from -0.0:
//   (i,j-1) (i,j+1) (i-1,j) (i+1,j) (i-1,j-1) (i+1,j+1) (i-1,j+1) (i+1,j-1)
// with missing neighbours skipped, and v' = v + (G*kc - v*kd), constrained components +0,
// u' = u + v'*dt (u: displacement from rest). The term of neighbour b on node a is
// d * spring_factor(l2, rest), d = (u_b - u_a) + rest offset (spring_vector below); the
// vertical term reused from the node below is the exact negation of the one computed there, which
// is literally what the CPU does (it subtracts the lower band).
//
// Float controls: SignedZeroInfNanPreserve is declared so the compiler may not fold x + 0.0 or
// 0.0 * x (signed zeros are part of the bits the parity suite compares). Denormals: see
// src/gpu/float_policy.h.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require

#include "shared/exact_math.h"
#include "shared/water_gpu.h"

spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve, 32-bit floats

layout(local_size_x = POND_STEP_LOCAL_X, local_size_y = 1, local_size_z = 1) in;
layout(constant_id = POND_SPEC_FAST_MATH) const bool kFastMath = false;
layout(constant_id = POND_SPEC_RSQRT_STEPS) const int kRsqrtSteps = kRsqrtStepsExact;

layout(std430, set = 0, binding = 0) restrict readonly buffer Src { float src[]; };
layout(std430, set = 0, binding = 1) restrict writeonly buffer Dst { float dst[]; };
layout(std430, set = 0, binding = 2) restrict readonly buffer Kinds { uint kinds[]; };
layout(push_constant) uniform Push { StepPush p; };

// Displacement u of node n from its rest position (sim/state.h: positions are stored as
// displacements, so a float keeps full precision however large the grid).
vec3 load_u(uint n) { return vec3(src[n], src[p.stride + n], src[2u * p.stride + n]); }

// The spring vector from node a to its neighbour b at column offset dj and row offset di (each
// -1, 0 or 1; constants after inlining): d = (u_b - u_a) + (dj, 0, di), where "+ 0" is not
// performed, exactly as the CPU kernel.
vec3 spring_vector(vec3 ua, vec3 ub, int dj, int di) {
  precise vec3 d = ub - ua;
  if (dj != 0) d.x = d.x + float(dj);
  if (di != 0) d.z = d.z + float(di);
  return d;
}

// Term of neighbour b on node a: d * (1 - rest * rsqrt(l2)), l2 = (dx*dx + dy*dy) + dz*dz.
vec3 term_exact(vec3 ua, vec3 ub, int dj, int di, float rest) {
  precise vec3 d = spring_vector(ua, ub, dj, di);
  precise float l2 = (d.x * d.x + d.y * d.y) + d.z * d.z;
  precise float f = spring_factor(l2, rest, kRsqrtSteps);
  precise vec3 t = d * f;
  return t;
}

// Fast mode: hardware inversesqrt, contraction allowed; its distance from exact is measured by
// the parity suite, not assumed.
vec3 term_fast(vec3 ua, vec3 ub, int dj, int di, float rest) {
  vec3 d = (ub - ua) + vec3(float(dj), 0.0, float(di));
  return d * (1.0 - rest * inversesqrt(dot(d, d)));
}

vec3 term(vec3 ua, vec3 ub, int dj, int di, float rest) {
  return kFastMath ? term_fast(ua, ub, dj, di, rest) : term_exact(ua, ub, dj, di, rest);
}

// acc + t where the neighbour exists, acc otherwise ("skipped").
vec3 accumulate(vec3 acc, vec3 t, bool exists) {
  precise vec3 sum = acc + t;
  return exists ? sum : acc;
}

void main() {
  const uint j = gl_GlobalInvocationID.x;
  const uint i0 = gl_GlobalInvocationID.y * POND_STEP_ROWS_PER_INVOCATION;
  if (j >= p.cols || i0 >= p.rows) return;
  const uint i1 = min(i0 + POND_STEP_ROWS_PER_INVOCATION, p.rows);
  const uint C = p.cols;
  const bool has_left = j > 0u, has_right = j + 1u < C;
  const uint jl = has_left ? j - 1u : j, jr = has_right ? j + 1u : j;

  // The window: displacements at columns (j-1, j, j+1) of rows i-1 (below), i (mid), i+1
  // (above); missing neighbours load the node itself (never used, but always in bounds).
  uint row = (i0 > 0u ? i0 - 1u : i0) * C;
  vec3 below_l = load_u(row + jl), below_m = load_u(row + j), below_r = load_u(row + jr);
  row = i0 * C;
  vec3 mid_l = load_u(row + jl), mid_m = load_u(row + j), mid_r = load_u(row + jr);
  vec3 carry = vec3(0.0);  // term of (i, j) on (i-1, j), from the previous row of the strip

  for (uint i = i0; i < i1; ++i) {
    const bool has_below = i > 0u, has_above = i + 1u < p.rows;
    row = (has_above ? i + 1u : i) * C;
    const vec3 above_l = load_u(row + jl), above_m = load_u(row + j), above_r = load_u(row + jr);

    // The spring to row i-1 is evaluated from its lower end, as the CPU does, and negated.
    const vec3 t_below = -((i == i0) ? term(below_m, mid_m, 0, 1, p.rest_edge) : carry);
    const vec3 t_above = term(mid_m, above_m, 0, 1, p.rest_edge);
    precise vec3 g = vec3(-0.0);
    g = accumulate(g, term(mid_m, mid_l, -1, 0, p.rest_edge), has_left);                 // (i, j-1)
    g = accumulate(g, term(mid_m, mid_r, 1, 0, p.rest_edge), has_right);                 // (i, j+1)
    g = accumulate(g, t_below, has_below);                                               // (i-1, j)
    g = accumulate(g, t_above, has_above);                                               // (i+1, j)
    g = accumulate(g, term(mid_m, below_l, -1, -1, p.rest_diag), has_below && has_left);  // (i-1, j-1)
    g = accumulate(g, term(mid_m, above_r, 1, 1, p.rest_diag), has_above && has_right);   // (i+1, j+1)
    g = accumulate(g, term(mid_m, below_r, 1, -1, p.rest_diag), has_below && has_right);  // (i-1, j+1)
    g = accumulate(g, term(mid_m, above_l, -1, 1, p.rest_diag), has_above && has_left);   // (i+1, j-1)
    carry = t_above;

    const uint n = i * C + j;
    const uint kind = (kinds[n >> 2u] >> ((n & 3u) * 8u)) & 0xffu;
    const uint s = p.stride;
    const vec3 v0 = vec3(src[3u * s + n], src[4u * s + n], src[5u * s + n]);
    precise vec3 v1 = v0 + ((g * p.kc) - (v0 * p.kd));
    // Constrained components become +0 (not v1 * 0, which could be -0 or NaN).
    if (kind != kNodeFree) v1.xz = vec2(0.0);
    if (kind == kNodeFixed) v1.y = 0.0;
    precise vec3 u1 = mid_m + v1 * p.dt;

    dst[n] = u1.x;
    dst[s + n] = u1.y;
    dst[2u * s + n] = u1.z;
    dst[3u * s + n] = v1.x;
    dst[4u * s + n] = v1.y;
    dst[5u * s + n] = v1.z;

    below_l = mid_l; below_m = mid_m; below_r = mid_r;
    mid_l = above_l; mid_m = above_m; mid_r = above_r;
  }
}
