#pragma once
// One substep of the water grid over a range of rows, written once against the wide-float
// operation table W (wide_scalar.h, wide_sse2.h, wide_avx2.h). Instantiated per backend in
// kernel_<backend>.cpp.
//
// The algorithm (the paper's optimized CPU loop, vectorized along a row):
//  - Each spring's force is computed once. For row i the kernel computes the horizontal springs
//    H(j) = (i,j)->(i,j+1) and the band of springs to row i+1: S(j) = (i,j)->(i+1,j),
//    D1(j) = (i,j)->(i+1,j+1), D2(j) = (i,j+1)->(i+1,j). The band of row i-1 is kept from the
//    previous row, so each spring is evaluated once per thread (the first row of a thread's range
//    re-evaluates its lower band; same inputs, same bits).
//  - Positions are displacements u from rest (state.h). The spring vector a->b, b being a's
//    neighbour at row offset di and column offset dj (each -1, 0 or 1), is
//        dx = (ux_b - ux_a) + dj,   dy = uy_b - uy_a,   dz = (uz_b - uz_a) + di,
//    where "+ 0" is not performed (so only dx of row springs, dz of column springs, both of
//    diagonals get an addition). The force term of spring a->b on a is  d * (1 - L * rsqrt(l2)),
//    l2 = (dx*dx + dy*dy) + dz*dz,  rsqrt = seed + Newton steps (shared/exact_math.h). On b it is
//    the exact negation (IEEE addition, subtraction and multiplication are sign-symmetric and the
//    offset flips sign with the direction), so evaluating it from either end, as the GPU does,
//    gives the same bits.
//  - CANONICAL SUMMATION ORDER (the GPU shader follows it): node (i,j) sums its neighbour terms,
//    starting from -0.0, in the order
//        (i,j-1) (i,j+1) (i-1,j) (i+1,j) (i-1,j-1) (i+1,j+1) (i-1,j+1) (i+1,j-1).
//    A missing neighbour (grid border) is skipped; here that is an addition of -0 or a subtraction
//    of +0, both the exact identity on every float including signed zeros.
//  - Integration (symplectic Euler, model.h):  v' = v + (G*kc - v*kd);  constrained velocity
//    components become +0;  u' = u + v'*dt.
#include <cstddef>
#include <cstdint>
#include <utility>

#include "shared/exact_math.h"
#include "sim/isa_namespace.h"
#include "sim/step_view.h"
#include "sim/wide_scalar.h"

// The kernel's helpers must be inlined into its loops: a call per 8 nodes costs more than the work.
#define POND_KERNEL_INLINE inline __attribute__((always_inline))

namespace pond::sim {
inline namespace POND_ISA {

// Offsets of the spring rows in the scratch (see step_view.h).
inline constexpr int kRowH = 0;
POND_KERNEL_INLINE constexpr int band_row(int band) { return 3 + 9 * band; }
inline constexpr int kBandS = 0, kBandD1 = 3, kBandD2 = 6;

// Calls fn.template operator()<V>(j) for chunks of V::width columns covering [begin, end): with W
// while at least W::width columns remain, the last chunk overlapping the previous one (it recomputes
// some columns from the same inputs: the same bits), or one column at a time with the scalar
// backend when the range is narrower than W.
template <class W, class Fn>
POND_KERNEL_INLINE void for_chunks(int begin, int end, Fn&& fn) {
  if (end - begin >= W::width) {
    int j = begin;
    for (; j + W::width <= end; j += W::width) fn.template operator()<W>(j);
    if (j < end) fn.template operator()<W>(end - W::width);
  } else {
    for (int j = begin; j < end; ++j) fn.template operator()<WideScalar>(j);
  }
}

// Steps: the Newton steps of the reciprocal square root, a compile-time constant so the four
// springs' iterations unroll and interleave.
template <class W, int Steps>
struct StepKernel {
  using F = typename W::F;

  POND_KERNEL_INLINE static F rsqrt(F x) {
    const F half_x = W::mul(x, W::set1(0.5f));
    F y = W::rsqrt_seed(x, shared::kRsqrtMagic);
    for (int k = 0; k < Steps; ++k) {
      F t = W::mul(y, y);
      t = W::mul(t, half_x);
      t = W::sub(W::set1(1.5f), t);
      y = W::mul(y, t);
    }
    return y;
  }

  struct Node {
    F x, y, z;
  };
  POND_KERNEL_INLINE static Node load(const StepView& v, std::size_t n) {
    return {W::load(v.ux + n), W::load(v.uy + n), W::load(v.uz + n)};
  }

  // The term of spring a->b on node a, b at column offset DJ and row offset DI from a, stored in
  // the three spring rows at `out` (x, y, z).
  template <int DJ, int DI>
  POND_KERNEL_INLINE static void spring(const Node& a, const Node& b, float rest, float* out) {
    F dx = W::sub(b.x, a.x);
    const F dy = W::sub(b.y, a.y);
    F dz = W::sub(b.z, a.z);
    if constexpr (DJ != 0) dx = W::add(dx, W::set1(static_cast<float>(DJ)));
    if constexpr (DI != 0) dz = W::add(dz, W::set1(static_cast<float>(DI)));
    const F l2 = W::add(W::add(W::mul(dx, dx), W::mul(dy, dy)), W::mul(dz, dz));
    const F f = W::sub(W::set1(1.0f), W::mul(W::set1(rest), rsqrt(l2)));
    W::store(out, W::mul(dx, f));
    W::store(out + kSlots, W::mul(dy, f));
    W::store(out + 2 * kSlots, W::mul(dz, f));
  }
};

// Fills slots [0, slots] of a band with a signed zero: +0 where the band is subtracted (below the
// row), -0 where it is added (above): either way the exact identity.
POND_KERNEL_INLINE void fill_band(float* scratch, int band, int slots, float zero) {
  float* b = scratch + band_row(band) * kSlots;
  for (int k = 0; k < 9; ++k)
    for (int s = 0; s <= slots; ++s) b[k * kSlots + s] = zero;
}

// The springs of row i that block [c0, c1) needs: H, D1, D2 at column indices
// [max(c0-1, 0), min(c1-1, C-2)], S at [c0, c1), into band `cur`; without a row above, band `cur`
// becomes -0. Missing indices -1 and C-1 get the signed zero that makes their use an identity.
template <class W, int Steps>
void block_springs(const StepView& v, int i, int c0, int c1, float* scratch, int cur) {
  const int C = v.cols;
  const bool band = i + 1 < v.rows;
  float* h = scratch + kRowH * kSlots;
  float* b = scratch + band_row(cur) * kSlots;
  const int slot0 = 1 - c0;  // slot of column j is j + slot0
  const std::size_t row = static_cast<std::size_t>(i) * C;
  const int lo = c0 > 0 ? c0 - 1 : 0, hi = c1 - 1 < C - 2 ? c1 - 1 : C - 2;
  const float re = v.k.rest_edge, rd = v.k.rest_diag;
  if (band) {
    // The four springs of a cell corner from the cell's four nodes, each loaded once. S is also
    // evaluated at index c0-1 (slot 0, never read); S(C-1), the one spring without a right
    // neighbour, is evaluated on its own.
    for_chunks<W>(lo, hi + 1, [&]<class V>(int j) {
      using K = StepKernel<V, Steps>;
      const std::size_t n = row + j;
      const auto a = K::load(v, n), e = K::load(v, n + 1), u = K::load(v, n + C),
                 ue = K::load(v, n + C + 1);
      const int s = j + slot0;
      K::template spring<1, 0>(a, e, re, h + s);                      // H:  (i,j) -> (i,j+1)
      K::template spring<0, 1>(a, u, re, b + kBandS * kSlots + s);    // S:  (i,j) -> (i+1,j)
      K::template spring<1, 1>(a, ue, rd, b + kBandD1 * kSlots + s);  // D1: (i,j) -> (i+1,j+1)
      K::template spring<-1, 1>(e, u, rd, b + kBandD2 * kSlots + s);  // D2: (i,j+1) -> (i+1,j)
    });
    if (c1 == C) {
      using K = StepKernel<WideScalar, Steps>;
      const std::size_t n = row + C - 1;
      K::template spring<0, 1>(K::load(v, n), K::load(v, n + C), re, b + kBandS * kSlots + C - 1 + slot0);
    }
  } else {
    for_chunks<W>(lo, hi + 1, [&]<class V>(int j) {
      using K = StepKernel<V, Steps>;
      const std::size_t n = row + j;
      K::template spring<1, 0>(K::load(v, n), K::load(v, n + 1), re, h + j + slot0);
    });
    fill_band(scratch, cur, c1 - c0, -0.0f);
  }
  for (int c = 0; c < 3; ++c) {
    if (c0 == 0) {  // index -1 is slot 0
      h[c * kSlots] = +0.0f;  // only subtracted (by node 0)
      if (band) {
        b[(kBandD1 + c) * kSlots] = +0.0f;  // only subtracted (as the lower band)
        b[(kBandD2 + c) * kSlots] = -0.0f;  // only added (as the upper band)
      }
    }
    if (c1 == C) {
      const int s = C - 1 + slot0;
      h[c * kSlots + s] = -0.0f;  // index C-1: only added (by node C-1)
      if (band) {
        b[(kBandD1 + c) * kSlots + s] = -0.0f;  // only added (as the upper band)
        b[(kBandD2 + c) * kSlots + s] = +0.0f;  // only subtracted (as the lower band)
      }
    }
  }
}

// Sums the spring terms of nodes [j, j + width) of row i in canonical order and integrates them.
// Returns `check` plus the new velocity components (non-finite iff the step blew up).
template <class W>
POND_KERNEL_INLINE typename W::F integrate_at(const StepView& v, int i, int j, int c0,
                                              const float* scratch, int below, int above,
                                              typename W::F check) {
  using F = typename W::F;
  const std::size_t n = static_cast<std::size_t>(i) * v.cols + j;
  const int s = j - c0 + 1;  // slot of column j
  const float* h = scratch + kRowH * kSlots + s;
  const float* lo = scratch + band_row(below) * kSlots + s;
  const float* up = scratch + band_row(above) * kSlots + s;
  const F kc = W::set1(v.k.kc), kd = W::set1(v.k.kd), dt = W::set1(v.k.dt);
  const typename W::M free_h = W::kind_below(v.kinds + n, 1);  // free nodes move horizontally
  const typename W::M free_v = W::kind_below(v.kinds + n, 2);  // free and vertical nodes move in y
  const float* const pos[3] = {v.ux, v.uy, v.uz};
  const float* const vel[3] = {v.vx, v.vy, v.vz};
  float* const opos[3] = {v.oux, v.ouy, v.ouz};
  float* const ovel[3] = {v.ovx, v.ovy, v.ovz};
  for (int c = 0; c < 3; ++c) {
    const int o = c * kSlots;
    F g = W::neg(W::load(h + o - 1));                          // (i, j-1)
    g = W::add(g, W::load(h + o));                             // (i, j+1)
    g = W::sub(g, W::load(lo + kBandS * kSlots + o));          // (i-1, j)
    g = W::add(g, W::load(up + kBandS * kSlots + o));          // (i+1, j)
    g = W::sub(g, W::load(lo + kBandD1 * kSlots + o - 1));     // (i-1, j-1)
    g = W::add(g, W::load(up + kBandD1 * kSlots + o));         // (i+1, j+1)
    g = W::sub(g, W::load(lo + kBandD2 * kSlots + o));         // (i-1, j+1)
    g = W::add(g, W::load(up + kBandD2 * kSlots + o - 1));     // (i+1, j-1)
    const F vel0 = W::load(vel[c] + n);
    F v1 = W::add(vel0, W::sub(W::mul(g, kc), W::mul(vel0, kd)));
    v1 = W::keep(c == 1 ? free_v : free_h, v1);
    W::store(ovel[c] + n, v1);
    W::store(opos[c] + n, W::add(W::load(pos[c] + n), W::mul(v1, dt)));
    check = W::add(check, v1);
  }
  return check;
}

// One substep for rows [r0, r1), block by block. Returns the sum of the new velocity components
// of those rows (non-finite iff some velocity is non-finite or astronomically large).
template <class W, int Steps>
float step_rows(const StepView& v, int r0, int r1, float* scratch) {
  typename W::F check = W::set1(0.0f);
  float tail_check = 0.0f;
  for (int c0 = 0; c0 < v.cols; c0 += kBlockCols) {
    const int c1 = c0 + kBlockCols < v.cols ? c0 + kBlockCols : v.cols;
    int below = 0, above = 1;
    if (r0 == 0) {
      fill_band(scratch, below, c1 - c0, +0.0f);  // no row -1: lower-band terms subtract +0
    } else {
      block_springs<W, Steps>(v, r0 - 1, c0, c1, scratch, below);
    }
    for (int i = r0; i < r1; ++i) {
      block_springs<W, Steps>(v, i, c0, c1, scratch, above);
      for_chunks<W>(c0, c1, [&]<class V>(int j) {
        if constexpr (V::width == W::width && W::width > 1)
          check = integrate_at<W>(v, i, j, c0, scratch, below, above, check);
        else
          tail_check = integrate_at<WideScalar>(v, i, j, c0, scratch, below, above, tail_check);
      });
      std::swap(below, above);
    }
  }
  return W::sum_lanes(check) + tail_check;
}

}  // namespace POND_ISA
}  // namespace pond::sim
