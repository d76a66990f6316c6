// The wind tree's GPU-facing declarations, shared by GLSL and C++: the vertex layout, the per-frame
// uniform block and the per-vertex bend formula. The future vertex shader and the CPU evaluation in
// src/tree (bend.cpp) call the very same functions, so their results agree to the bit.
//
// The article's bend (Ilyin 2008, SPEC section 2): every vertex carries its rest position, the
// displacement vectors wX and wZ for unit wind along x and along z (already summed along the chain
// of branches that carry it), and three twig-jitter coefficients. Per frame the shader receives the
// inertial, gusty wind (wind.x, wind.z) and the twig noise q; then
//     jitter = dot(coeffs, q)
//     p      = pos + wX * (wind.x + jitter) + wZ * (wind.z + jitter)
//
// Exactness: the sums are written out in one fixed order and marked `precise` (no FMA contraction);
// C++ is built with -ffp-contract=off. So the same inputs give the same bits on both sides.
#ifndef POND_TREE_WIND_H
#define POND_TREE_WIND_H

#include "exact_math.h"

#ifdef __cplusplus
#include <cstddef>
#define POND_CONST inline constexpr
#define POND_FN inline
namespace pond::shared::tree_wind {
// Just enough of GLSL's vec3/vec4 for the code below, in this header's own namespace so that other
// shared headers may declare their own without a clash.
struct vec3 {
  float x = 0, y = 0, z = 0;
};
struct vec4 {
  float x = 0, y = 0, z = 0, w = 0;
};
inline vec3 operator+(vec3 a, vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline vec3 operator-(vec3 a, vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec3 operator*(vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
inline bool operator==(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
#else
#define POND_CONST const
#define POND_FN
#endif

// ---- Vertex layout -------------------------------------------------------------------------------
// One vertex is 12 floats, tightly packed (the rows of `pond tree`'s PREFIX.vertices.npy):
// position, wind vector X, wind vector Z, jitter coefficients. As vertex attributes they sit at the
// locations below with byte offsets 4 * the float offsets; a storage buffer reads them as float[12]
// (a vec3 array would be padded to 16 bytes in std430).
POND_CONST int kTreeVertexFloats = 12;
POND_CONST int kTreeVertexPosition = 0;
POND_CONST int kTreeVertexWindX = 3;
POND_CONST int kTreeVertexWindZ = 6;
POND_CONST int kTreeVertexJitter = 9;

POND_CONST int kTreeAttribPosition = 0;
POND_CONST int kTreeAttribWindX = 1;
POND_CONST int kTreeAttribWindZ = 2;
POND_CONST int kTreeAttribJitter = 3;

// Bend modes (TreeWindFrame::bend_mode).
POND_CONST uint kTreeBendArticle = 0u;     // the article's displacement: branches stretch
POND_CONST uint kTreeBendKeepLength = 1u;  // each segment renormalized to its rest length

// ---- Per-frame uniform block (std140 and std430 give the same layout: 48 bytes) ---------------------
struct TreeWindFrame {
  vec4 wind;        // (wind.x, 0, wind.z, 0): the inertial, gusty wind; wind is never vertical
  vec4 twig;        // (q.x, q.y, q.z, 0): q = (noise(t*33), noise(t*52), noise(t*94)) * 10 * |W|
  float time;       // seconds of wind time, including this instance's phase
  float strength;   // |W|, the user wind's length (q already carries it; for shading, leaves)
  uint bend_mode;   // kTreeBendArticle or kTreeBendKeepLength
  uint pad0;
};

// ---- The bend formula --------------------------------------------------------------------------
// jitter = dot(coeffs, q), summed x, y, z in this order.
POND_FN float tree_wind_jitter(vec3 coeffs, vec3 q) {
  POND_PRECISE float j = coeffs.x * q.x;
  j = j + coeffs.y * q.y;
  j = j + coeffs.z * q.z;
  return j;
}

// The article's bent position: p = pos + wX * (wind_x + jitter) + wZ * (wind_z + jitter).
POND_FN vec3 tree_wind_bend(vec3 pos, vec3 wind_vec_x, vec3 wind_vec_z, vec3 coeffs, float wind_x,
                            float wind_z, vec3 q) {
  POND_PRECISE float jitter = tree_wind_jitter(coeffs, q);
  POND_PRECISE float ax = wind_x + jitter;
  POND_PRECISE float az = wind_z + jitter;
  POND_PRECISE vec3 p = pos + wind_vec_x * ax;
  p = p + wind_vec_z * az;
  return p;
}

// A segment's rest length, |tip - parent|, with the exact reciprocal square root (l2 * 1/sqrt(l2)),
// so that the CPU and the GPU rescale to the same length.
POND_FN float tree_wind_rest_length(vec3 parent, vec3 tip) {
  POND_PRECISE vec3 d = tip - parent;
  POND_PRECISE float l2 = d.x * d.x;
  l2 = l2 + d.y * d.y;
  l2 = l2 + d.z * d.z;
  POND_PRECISE float l = l2 * rsqrt_exact(l2, kRsqrtStepsExact);
  return l;
}

// One step of the length-preserving variant, walked from the root (parents before children): the
// segment parent -> tip keeps the direction the article's formula gives it (bent_tip - bent_parent)
// but its rest length, and hangs from the parent's already length-preserved position. So no branch
// stretches, and the shape follows the article's. 1/length uses the exact reciprocal square root, so
// CPU and GPU agree here too; a zero-length bent segment yields kept_parent, never NaN.
POND_FN vec3 tree_wind_keep_length(vec3 kept_parent, vec3 bent_parent, vec3 bent_tip,
                                   float rest_length) {
  POND_PRECISE vec3 d = bent_tip - bent_parent;
  POND_PRECISE float l2 = d.x * d.x;
  l2 = l2 + d.y * d.y;
  l2 = l2 + d.z * d.z;
  POND_PRECISE float scale = rest_length * rsqrt_exact(l2, kRsqrtStepsExact);
  if (l2 == 0.0f) scale = 0.0f;
  POND_PRECISE vec3 p = kept_parent + d * scale;
  return p;
}

#ifdef __cplusplus
// One vertex as the vertex buffer and PREFIX.vertices.npy hold it.
struct TreeVertex {
  vec3 position;
  vec3 wind_x;  // displacement per unit wind along +x, summed with the carrying branches'
  vec3 wind_z;  // the same for +z
  vec3 jitter;  // twig-jitter coefficients; zero except on the three thinnest levels
};
static_assert(sizeof(vec3) == 12 && sizeof(vec4) == 16);
static_assert(sizeof(TreeVertex) == kTreeVertexFloats * sizeof(float));
static_assert(offsetof(TreeVertex, position) == kTreeVertexPosition * sizeof(float));
static_assert(offsetof(TreeVertex, wind_x) == kTreeVertexWindX * sizeof(float));
static_assert(offsetof(TreeVertex, wind_z) == kTreeVertexWindZ * sizeof(float));
static_assert(offsetof(TreeVertex, jitter) == kTreeVertexJitter * sizeof(float));

static_assert(sizeof(TreeWindFrame) == 48);
static_assert(offsetof(TreeWindFrame, wind) == 0);
static_assert(offsetof(TreeWindFrame, twig) == 16);
static_assert(offsetof(TreeWindFrame, time) == 32);
static_assert(offsetof(TreeWindFrame, strength) == 36);
static_assert(offsetof(TreeWindFrame, bend_mode) == 40);
}  // namespace pond::shared::tree_wind
#endif
#undef POND_CONST
#undef POND_FN
#endif
