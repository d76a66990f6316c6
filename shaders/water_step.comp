#version 460
// One substep of the water grid: spring forces and semi-implicit (symplectic) Euler, state A -> state B.
//
// Speed on lavapipe (llvmpipe runs 8 invocations as the lanes of one AVX2 register; what decides
// the speed is the number of memory operations per node, not the arithmetic):
//  - An SSBO access with a per-invocation address becomes a loop over the 8 lanes with two
//    branches per lane (exec mask, bounds); a texel-buffer fetch is a straight-line gather. So
//    the state is read through texel-buffer views of the same SoA buffers (shared/water_gpu.h;
//    the layout is unchanged) and written with vec4 stores (below).
//  - One algorithm, the quad path (every grid): one invocation owns 4 consecutive columns of a strip
//    of POND_STEP_ROWS_PER_INVOCATION rows. A node row of the 4 columns is one RGBA32F texel per
//    component (16-byte aligned because the row pitch and the stride are multiples of 4: rows are
//    p.pitch = cols rounded up to 4 nodes apart, see "Padding" below),
//    plus the two side neighbours as R32F texels; velocities, outputs and the 4 kinds (RGBA8UI)
//    are one texel each; the 6 outputs are vec4 SSBO stores (one lane loop per 4 floats, where a
//    RGBA32F imageStore loops over lanes x channels). 19 memory operations per 4 nodes instead of
//    19 per node. Within
//    the invocation each spring is evaluated once: per row 5 horizontal springs and the band to
//    the row above (4 vertical, 5 + 5 diagonal), the band kept as the next row's lower band
//    (4.75 spring evaluations per node instead of 8). In SoA code the column shuffles are free.
//  - Workgroup shape: local_size_x is a specialization constant; the solver makes a workgroup
//    span the whole row strip (up to POND_STEP_LOCAL_X_MAX = 256 invocations, a 1024-wide grid).
//    With the barrier per row (main_quad) a group then reads and writes each row
//    as one contiguous run per component, which the hardware prefetcher follows.
//  - Stores: Mesa 22.3's llvmpipe stores per lane and per scalar component (exec test, bounds
//    compare and branch, one store each), so with 32-bit types the stores dominate the cost;
//    a 64-bit store moves 8 bytes per lane step. So where the device has shaderInt64 the solver
//    uses the POND_STEP_INT64_STORES variant (built as water_step_int64, see store4): two
//    u64 components per 4 floats, the float bits packed unchanged. The parity suite runs it and,
//    forced, the vec4 variant.
// The measured figures, the profile of the JIT code and the variants tried and dropped are in
// docs/perf.md.
//
// Exact mode (kFastMath false) is bit-identical to the CPU kernel (src/sim/step_kernel.h): every
// operation `precise` (no FMA contraction), the Newton rsqrt of shared/exact_math.h (only + - *),
// the canonical summation order starting from -0.0:
//   (i,j-1) (i,j+1) (i-1,j) (i+1,j) (i-1,j-1) (i+1,j+1) (i-1,j+1) (i+1,j-1)
// with missing neighbours skipped, and v' = v + (G*kc - v*kd), constrained components +0,
// u' = u + v'*dt (u: displacement from rest). Each spring is evaluated from the end the CPU uses
// (the lower row, or the left column), d = (u_b - u_a) + rest offset (spring_vector below), and
// used negated at its other end, which is literally what the CPU does (it subtracts it).
//
// Padding: the last group of 4 columns of a row may hold pitch - cols (1 to 3) padding columns
// past the grid. For a real node they are missing right neighbours: every term of a spring to a
// padding column, (i, j+1), (i+1, j+1) and (i-1, j+1), is computed and skipped (accumulate with
// exists = false), exactly as at the right border of a grid whose width is a multiple of 4; its
// left, upper and lower neighbours are never padding. So no padding value reaches a real node's
// bits. The padding nodes themselves are fixed (their kind, set by the solver) and start at +0, so
// integrate() stores v' = +0 and u' = +0 + +0 * dt = +0 into them every substep, whatever their
// spring sum (even NaN): the state's padding stays +0 for good, and the perturbation tables never
// name it.
//
// Float controls: SignedZeroInfNanPreserve is declared so the compiler may not fold x + 0.0 or
// 0.0 * x (signed zeros are part of the bits the parity suite compares). Denormals: see
// src/gpu/float_policy.h. R32F/RGBA32F texel fetches and stores move the float bits unchanged.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require
#ifdef POND_STEP_INT64_STORES
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#endif

#include "shared/exact_math.h"
#include "shared/water_gpu.h"

spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve, 32-bit floats
#ifdef POND_DENORM_PRESERVE  // the variant for devices with shaderDenormPreserveFloat32 (float_policy.h)
spirv_execution_mode(capabilities = [4464], 4459, 32);  // DenormPreserve, 32-bit floats
#endif

layout(local_size_x = POND_STEP_LOCAL_X, local_size_y = 1, local_size_z = 1) in;
layout(local_size_x_id = POND_SPEC_STEP_LOCAL_X) in;
layout(constant_id = POND_SPEC_FAST_MATH) const bool kFastMath = false;
layout(constant_id = POND_SPEC_RSQRT_STEPS) const int kRsqrtSteps = kRsqrtStepsExact;
layout(constant_id = POND_SPEC_PADDED_ROWS) const bool kPaddedRows = true;
// Scenes with bodies: the largest |u'x|, |u'z| written goes to `reach_bits` (the contact's bound
// on how far a node can have moved sideways, shared/bodies.h), as an atomic max of the float bits
// (non-negative floats order as their bits); the contact pass reads it and sets it back to 0.
layout(constant_id = POND_SPEC_TRACK_REACH) const bool kTrackReach = false;

// The bindings of shared/water_gpu.h (POND_STEP_BINDING_*): views of the source state, the
// destination state and the kinds.
layout(set = 0, binding = POND_STEP_BINDING_SRC1) uniform samplerBuffer src1;  // R32F: float n
layout(set = 0, binding = POND_STEP_BINDING_SRC4) uniform samplerBuffer src4;  // RGBA32F: floats 4n..4n+3
#ifdef POND_STEP_INT64_STORES
// 64-bit stores (devices with shaderInt64): llvmpipe stores per lane and per scalar component, so
// two 64-bit components move a group of 4 floats in half the iterations of a vec4. The float bits
// are packed unchanged (floatBitsToUint, packUint2x32: x in the low half, as in memory).
layout(std430, set = 0, binding = POND_STEP_BINDING_DST4) restrict writeonly buffer Dst8 { u64vec2 dst8[]; };
void store4(uint index, vec4 v) {
  dst8[index] = u64vec2(packUint2x32(floatBitsToUint(v.xy)), packUint2x32(floatBitsToUint(v.zw)));
}
#else
layout(std430, set = 0, binding = POND_STEP_BINDING_DST4) restrict writeonly buffer Dst4 { vec4 dst4[]; };
void store4(uint index, vec4 v) { dst4[index] = v; }
#endif
layout(set = 0, binding = POND_STEP_BINDING_KINDS4) uniform usamplerBuffer kinds4;  // RGBA8UI: nodes 4n..4n+3
layout(std430, set = 0, binding = POND_STEP_BINDING_REACH) restrict buffer Reach { uint reach_bits; };
shared uint group_reach;
layout(push_constant) uniform Push { StepPush p; };

float load1(uint n) { return texelFetch(src1, int(n)).x; }
vec4 load4(uint q) { return texelFetch(src4, int(q)); }

// Displacement u of node n from its rest position (sim/state.h: positions are stored as
// displacements, so a float keeps full precision however large the grid).

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

// Fast mode: the hardware inversesqrt refined by one Newton step, contraction allowed. Vulkan only
// bounds inversesqrt to 2 ulp; one step squares that relative error (to ~1e-13), so the result is
// within rounding of 1/sqrt on any device and fast mode's distance from exact, which the parity
// suite measures, is the same everywhere. The rest lengths are calibrated for such an accurate
// rsqrt (sim::gpu_rest_lengths), so a spring at rest has no tension.
vec3 term_fast(vec3 ua, vec3 ub, int dj, int di, float rest) {
  vec3 d = (ub - ua) + vec3(float(dj), 0.0, float(di));
  const float l2 = dot(d, d);
  float y = inversesqrt(l2);
  y = y * (1.5 - (0.5 * l2) * (y * y));
  return d * (1.0 - rest * y);
}

vec3 term(vec3 ua, vec3 ub, int dj, int di, float rest) {
  return kFastMath ? term_fast(ua, ub, dj, di, rest) : term_exact(ua, ub, dj, di, rest);
}

vec3 neg(vec3 t) {
  precise vec3 r = -t;
  return r;
}

// acc + t where the neighbour exists, acc otherwise ("skipped").
vec3 accumulate(vec3 acc, vec3 t, bool exists) {
  precise vec3 sum = acc + t;
  return exists ? sum : acc;
}

// Semi-implicit Euler of one node: v' = v + (G*kc - v*kd), constrained components +0 (not v' * 0,
// which could be -0 or NaN), u' = u + v'*dt. Returns u' in out_u, v' in out_v.
void integrate(vec3 u0, vec3 v0, vec3 g, uint kind, out vec3 out_u, out vec3 out_v) {
  precise vec3 v1 = v0 + ((g * p.kc) - (v0 * p.kd));
  if (kind != kNodeFree) v1.xz = vec2(0.0);
  if (kind == kNodeFixed) v1.y = 0.0;
  precise vec3 u1 = u0 + v1 * p.dt;
  out_u = u1;
  out_v = v1;
}

// ---- Quad path: 4 columns per invocation. ----

// Row i of the group at columns j0-1 .. j0+4 (index 0 .. 5); a missing side neighbour loads the
// nearest column of the group (never used, always in bounds).
void load_row(uint i, uint q, uint j0, bool has_l, bool has_r, out vec3 u[6]) {
  const uint n0 = i * p.pitch + j0;
  const uint nl = has_l ? n0 - 1u : n0, nr = has_r ? n0 + 4u : n0 + 3u;
  const uint q4 = p.stride >> 2u, s = p.stride;
  const vec4 x = load4(q), y = load4(q4 + q), z = load4(2u * q4 + q);
  u[0] = vec3(load1(nl), load1(s + nl), load1(2u * s + nl));
  u[1] = vec3(x.x, y.x, z.x);
  u[2] = vec3(x.y, y.y, z.y);
  u[3] = vec3(x.z, y.z, z.z);
  u[4] = vec3(x.w, y.w, z.w);
  u[5] = vec3(load1(nr), load1(s + nr), load1(2u * s + nr));
}

// The band of springs from row `lo` (index 0..5 = columns j0-1 .. j0+4) to the row above `up`,
// each evaluated from its lower end as the CPU does:
//   s[k]  = (i, j0+k)   -> (i+1, j0+k),    k = 0..3
//   d1[m] = (i, j0+m-1) -> (i+1, j0+m),    m = 0..4
//   d2[m] = (i, j0+m)   -> (i+1, j0+m-1),  m = 0..4
// (Written out, not looped: llvmpipe keeps an array indexed by a loop counter in memory, with a
// per-lane loop for every access; constant indices make every element a register.)
#define POND_BAND_S(k) s[k] = term(lo[k + 1], up[k + 1], 0, 1, p.rest_edge)
#define POND_BAND_D(m) \
  d1[m] = term(lo[m], up[m + 1], 1, 1, p.rest_diag); \
  d2[m] = term(lo[m + 1], up[m], -1, 1, p.rest_diag)
void band(vec3 lo[6], vec3 up[6], out vec3 s[4], out vec3 d1[5], out vec3 d2[5]) {
  POND_BAND_S(0); POND_BAND_S(1); POND_BAND_S(2); POND_BAND_S(3);
  POND_BAND_D(0); POND_BAND_D(1); POND_BAND_D(2); POND_BAND_D(3); POND_BAND_D(4);
}

void main_quad() {
  const uint Q = p.pitch >> 2u;  // groups of 4 columns per row (the last may end in padding)
  const uint i0 = gl_WorkGroupID.y * POND_STEP_ROWS_PER_INVOCATION;
  if (i0 >= p.rows) return;  // uniform in the workgroup
  // Invocations past the last group compute group Q-1 again and store nothing: every invocation
  // stays in the row loop, whose barrier() must be reached by the whole workgroup.
  const bool in_grid = gl_GlobalInvocationID.x < Q;
  const uint q0 = min(gl_GlobalInvocationID.x, Q - 1u);
  const uint i1 = min(i0 + POND_STEP_ROWS_PER_INVOCATION, p.rows);
  const uint j0 = 4u * q0;
  const bool has_l = q0 > 0u, has_r = q0 + 1u < Q;
  // Whether column j0+k has its right neighbour j0+k+1 in the grid (not padding, not past the
  // row); for k = 3 that is has_r (j0+4 < pitch <=> j0+4 < cols, the pitch being cols rounded
  // up to 4). Only the last group of a padded row can have a false one; without padding they
  // are constants (kPaddedRows false), so grids whose width is a multiple of 4 do not pay for
  // three per-lane flags.
  const bool r0 = !kPaddedRows || j0 + 1u < p.cols, r1 = !kPaddedRows || j0 + 2u < p.cols,
             r2 = !kPaddedRows || j0 + 3u < p.cols;
  const uint q4 = p.stride >> 2u;

  vec3 mid[6], up[6];
  vec4 reach = vec4(0.0);  // the largest |u'x|, |u'z| of the invocation's nodes (kTrackReach)
  load_row(i0, i0 * Q + q0, j0, has_l, has_r, mid);
  // The lower band of row i0 (re-evaluated from row i0-1: the same inputs, the same bits).
  vec3 bs[4], bd1[5], bd2[5];
  {
    vec3 lo[6];
    const uint il = i0 > 0u ? i0 - 1u : i0;
    load_row(il, il * Q + q0, j0, has_l, has_r, lo);
    band(lo, mid, bs, bd1, bd2);
  }

  for (uint i = i0; i < i1; ++i) {
    const bool has_below = i > 0u, has_above = i + 1u < p.rows;
    const uint q = i * Q + q0;
    const uint ia = has_above ? i + 1u : i;
    load_row(ia, ia * Q + q0, j0, has_l, has_r, up);

    vec3 h[5];  // h[k] = (i, j0+k-1) -> (i, j0+k)
#define POND_H(k) h[k] = term(mid[k], mid[k + 1], 1, 0, p.rest_edge)
    POND_H(0); POND_H(1); POND_H(2); POND_H(3); POND_H(4);
    vec3 s[4], d1[5], d2[5];
    band(mid, up, s, d1, d2);

    const vec4 vx = load4(3u * q4 + q), vy = load4(4u * q4 + q), vz = load4(5u * q4 + q);
    const uvec4 kind = texelFetch(kinds4, int(q));
    vec3 u1[4], v1[4];
#define POND_NODE(k, l, r)                                                                    \
  {                                                                                           \
    precise vec3 g = vec3(-0.0);                                                              \
    g = accumulate(g, neg(h[k]), l);                     /* (i, j-1) */                       \
    g = accumulate(g, h[k + 1], r);                      /* (i, j+1) */                       \
    g = accumulate(g, neg(bs[k]), has_below);            /* (i-1, j) */                       \
    g = accumulate(g, s[k], has_above);                  /* (i+1, j) */                       \
    g = accumulate(g, neg(bd1[k]), has_below && (l));    /* (i-1, j-1) */                     \
    g = accumulate(g, d1[k + 1], has_above && (r));      /* (i+1, j+1) */                     \
    g = accumulate(g, neg(bd2[k + 1]), has_below && (r)); /* (i-1, j+1) */                    \
    g = accumulate(g, d2[k], has_above && (l));          /* (i+1, j-1) */                     \
    integrate(mid[k + 1], vec3(vx[k], vy[k], vz[k]), g, kind[k], u1[k], v1[k]);               \
  }
    POND_NODE(0, has_l, r0)
    POND_NODE(1, true, r1)
    POND_NODE(2, true, r2)
    POND_NODE(3, true, has_r)
    const vec4 ox = vec4(u1[0].x, u1[1].x, u1[2].x, u1[3].x);
    const vec4 oy = vec4(u1[0].y, u1[1].y, u1[2].y, u1[3].y);
    const vec4 oz = vec4(u1[0].z, u1[1].z, u1[2].z, u1[3].z);
    const vec4 ovx = vec4(v1[0].x, v1[1].x, v1[2].x, v1[3].x);
    const vec4 ovy = vec4(v1[0].y, v1[1].y, v1[2].y, v1[3].y);
    const vec4 ovz = vec4(v1[0].z, v1[1].z, v1[2].z, v1[3].z);
    if (kTrackReach) reach = max(reach, max(abs(ox), abs(oz)));
    if (in_grid) {
      store4(q, ox);
      store4(q4 + q, oy);
      store4(2u * q4 + q, oz);
      store4(3u * q4 + q, ovx);
      store4(4u * q4 + q, ovy);
      store4(5u * q4 + q, ovz);
    }
    // Not for shared data: llvmpipe runs the workgroup 8 invocations at a time, and a barrier
    // makes it run row i for all of them before row i+1 (coroutines), so the row (the group's
    // part of it: all of it when the group spans the row) is read and written as one contiguous
    // run per component instead of 128 bytes per 4 KB page.
    barrier();

    bs = s; bd1 = d1; bd2 = d2;
    mid = up;
  }
  if (kTrackReach) {  // one global atomic per workgroup (the group's invocations meet in shared memory)
    if (gl_LocalInvocationIndex == 0u) group_reach = 0u;
    barrier();
    atomicMax(group_reach, floatBitsToUint(max(max(reach.x, reach.y), max(reach.z, reach.w))));
    barrier();
    if (gl_LocalInvocationIndex == 0u) atomicMax(reach_bits, group_reach);
  }
}

void main() { main_quad(); }
