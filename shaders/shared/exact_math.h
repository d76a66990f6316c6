// Exact math shared by GLSL and C++: this file is included by the compute shaders and by the CPU
// solver, so the constants and the scalar reference of every exact operation exist once.
//
// Why it is exact: Vulkan requires +, - and * on 32-bit floats to be correctly rounded, but not
// division, sqrt or inversesqrt. The reciprocal square root 1/sqrt(x) is therefore built from the
// classic bit-trick seed and Newton steps y <- y * (1.5 - (x/2) * y * y) that use only +, - and *.
// With every operation marked `precise` in GLSL (no FMA contraction) and C++ built with
// -ffp-contract=off, every backend performs the same roundings in the same order: the same bits.
//
// The canonical operation order of one Newton step, which every backend (scalar, SSE2, AVX2, GLSL)
// follows literally:   t = y * y;  t = t * half_x;  t = 1.5 - t;  y = y * t;
// with half_x = x * 0.5 computed once.
#ifndef POND_EXACT_MATH_H
#define POND_EXACT_MATH_H

#ifdef __cplusplus
#include <bit>
#include <cstdint>
#define POND_PRECISE
#define POND_CONST inline constexpr
#define POND_FN inline
namespace pond::shared {
using uint = std::uint32_t;
inline float uintBitsToFloat(uint u) { return std::bit_cast<float>(u); }
inline uint floatBitsToUint(float f) { return std::bit_cast<uint>(f); }
#else
#define POND_PRECISE precise
#define POND_CONST const
#define POND_FN
#endif

// 0x5f3759df: the seed constant of the fast inverse square root; its relative error after one
// Newton step is below 1.8e-3, after two below 4.7e-6, after three at float rounding level.
POND_CONST uint kRsqrtMagic = 0x5f3759dfu;
// Exact mode: three Newton steps (float accuracy). Fast mode on the CPU: two.
POND_CONST int kRsqrtStepsExact = 3;
POND_CONST int kRsqrtStepsFast = 2;

// Node kinds in the constraint mask (one per node).
POND_CONST uint kNodeFree = 0u;
POND_CONST uint kNodeVertical = 1u;  // x and z held, y free
POND_CONST uint kNodeFixed = 2u;     // never moves

// Scalar reference of the exact reciprocal square root, for normal floats x > 0. (x = 0, two
// coincident nodes, gives NaN, which stops the run as a blow-up.)
POND_FN float rsqrt_exact(float x, int steps) {
  POND_PRECISE float half_x = x * 0.5f;
  POND_PRECISE float y = uintBitsToFloat(kRsqrtMagic - (floatBitsToUint(x) >> 1u));
  for (int k = 0; k < steps; ++k) {
    POND_PRECISE float t = y * y;
    t = t * half_x;
    t = 1.5f - t;
    y = y * t;
  }
  return y;
}

// Hooke's stretch factor of a spring with squared length l2 and rest length `rest`:
// the force on its first node is (x_b - x_a) * stiffness * spring_factor(l2, rest).
POND_FN POND_PRECISE float spring_factor(float l2, float rest, int steps) {
  POND_PRECISE float r = rsqrt_exact(l2, steps);
  POND_PRECISE float s = rest * r;
  return 1.0f - s;
}

// x with a zero made +0: the sign of a zero may differ between two compilers' equivalent
// expressions, and it is part of the compared bits. On the bits, since a compiler may drop x + 0.0
// (lavapipe does, SignedZeroInfNanPreserve or not).
POND_FN float plus_zero(float x) { return floatBitsToUint(x) == 0x80000000u ? 0.0f : x; }

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#undef POND_CONST
#undef POND_FN
#endif
