#pragma once
// One substep of the water grid over a range of rows, written once against the wide-float
// operation table W (wide_scalar.h, wide_sse2.h, wide_avx2.h, wide_avx512.h). Instantiated per
// backend in kernel_<backend>.cpp.
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

// Offsets of the spring rows in the scratch (see step_view.h): two rows of H springs (x, y, z
// each; row i's and row i+1's) and three bands of S, D1, D2 (x, y, z each; rows i-1, i, i+1).
POND_KERNEL_INLINE constexpr int h_row(int h) { return 3 * h; }
POND_KERNEL_INLINE constexpr int band_row(int band) { return 6 + 9 * band; }
inline constexpr int kBandS = 0, kBandD1 = 3, kBandD2 = 6;

// Calls fn.template operator()<V, Shifted>(j) for chunks of V::width columns [j, j + V::width)
// covering [begin, end): chunks of W while more than W::width columns remain, then one last chunk
// ending at `end`, which overlaps the one before it where the columns do not divide evenly (it
// recomputes some columns from the same inputs: the same bits). The last chunk is a chunk of
// W::Half (half as wide; half the cost where the wide unit is split in two, as on Zen 4) when that
// covers the rest. Shifted is true for a last chunk that starts before the columns not done yet.
// A range narrower than W is done with W::Half, or one column at a time with the scalar backend.
template <class W, class Fn>
POND_KERNEL_INLINE void for_chunks(int begin, int end, Fn&& fn) {
  using H = typename W::Half;
  if (end - begin >= W::width) {
    int j = begin;
    for (; end - j > W::width; j += W::width) fn.template operator()<W, false>(j);
    if constexpr (H::width < W::width) {
      if (end - j <= H::width) {
        if (end - j < H::width)
          fn.template operator()<H, true>(end - H::width);
        else
          fn.template operator()<H, false>(j);
        return;
      }
    }
    if (end - j < W::width)
      fn.template operator()<W, true>(end - W::width);
    else
      fn.template operator()<W, false>(j);
  } else if constexpr (H::width < W::width) {
    for_chunks<H>(begin, end, fn);
  } else {
    for (int j = begin; j < end; ++j) fn.template operator()<WideScalar, false>(j);
  }
}

// Steps: the Newton steps of the reciprocal square root, a compile-time constant so the four
// springs' iterations unroll and interleave.
template <class W, int Steps>
struct StepKernel {
  using F = typename W::F;

  struct Node {
    F x, y, z;
  };
  POND_KERNEL_INLINE static Node load(const StepView& v, std::size_t n) {
    return {W::load(v.ux + n), W::load(v.uy + n), W::load(v.uz + n)};
  }

  // A spring a->b: its vector (b at column offset DJ and row offset DI from a), rest length and
  // the three spring rows at `out` (x, y, z) its term on a goes to.
  struct Spring {
    F dx, dy, dz;
    float rest;
    float* out;
  };
  template <int DJ, int DI>
  POND_KERNEL_INLINE static Spring vec(const Node& a, const Node& b, float rest, float* out) {
    F dx = W::sub(b.x, a.x);
    const F dy = W::sub(b.y, a.y);
    F dz = W::sub(b.z, a.z);
    if constexpr (DJ != 0) dx = W::add(dx, W::set1(static_cast<float>(DJ)));
    if constexpr (DI != 0) dz = W::add(dz, W::set1(static_cast<float>(DI)));
    return {dx, dy, dz, rest, out};
  }

  // Reciprocal square roots of K values, stage by stage, so that their K independent chains of
  // dependent operations (the Newton steps are serial) interleave in the instruction stream:
  //   hx = x * 0.5;  y = seed(x);  Steps times: y = y * (1.5 - (y*y) * hx).
  template <int K>
  POND_KERNEL_INLINE static void rsqrt_n(const F (&x)[K], F (&y)[K]) {
    F hx[K], t[K];
    for (int k = 0; k < K; ++k) hx[k] = W::mul(x[k], W::set1(0.5f));
    for (int k = 0; k < K; ++k) y[k] = W::rsqrt_seed(x[k], shared::kRsqrtMagic);
    for (int step = 0; step < Steps; ++step) {
      for (int k = 0; k < K; ++k) t[k] = W::mul(y[k], y[k]);
      for (int k = 0; k < K; ++k) t[k] = W::mul(t[k], hx[k]);
      for (int k = 0; k < K; ++k) t[k] = W::sub(W::set1(1.5f), t[k]);
      for (int k = 0; k < K; ++k) y[k] = W::mul(y[k], t[k]);
    }
  }
  POND_KERNEL_INLINE static F rsqrt(F x) {
    const F in[1] = {x};
    F out[1];
    rsqrt_n(in, out);
    return out[0];
  }

  // The terms d * (1 - L * rsqrt(l2)), l2 = (dx*dx + dy*dy) + dz*dz, of K springs, each stage for
  // all K before the next (see rsqrt_n).
  template <int K>
  POND_KERNEL_INLINE static void springs(const Spring (&s)[K]) {
    F l2[K], y[K];
    for (int k = 0; k < K; ++k)
      l2[k] = W::add(W::add(W::mul(s[k].dx, s[k].dx), W::mul(s[k].dy, s[k].dy)),
                     W::mul(s[k].dz, s[k].dz));
    rsqrt_n(l2, y);
    for (int k = 0; k < K; ++k) {
      const F f = W::sub(W::set1(1.0f), W::mul(W::set1(s[k].rest), y[k]));
      W::store(s[k].out, W::mul(s[k].dx, f));
      W::store(s[k].out + kSlots, W::mul(s[k].dy, f));
      W::store(s[k].out + 2 * kSlots, W::mul(s[k].dz, f));
    }
  }

  // The term of spring a->b on node a, b at column offset DJ and row offset DI from a, stored in
  // the three spring rows at `out` (x, y, z).
  template <int DJ, int DI>
  POND_KERNEL_INLINE static void spring(const Node& a, const Node& b, float rest, float* out) {
    const Spring one[1] = {vec<DJ, DI>(a, b, rest, out)};
    springs<1>(one);
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
// [lo, hi] = [max(c0-1, 0), min(c1-1, C-2)] into H row `hs` and band `cur`, S at [c0, c1) into
// band `cur`; without a row below, band `cur` becomes -0. Missing indices -1 and C-1 get the signed
// zero that makes their use an identity: for_chunks over [lo, hi] with this object, then finish().
template <class W, int Steps>
struct RowSprings {
  const StepView& v;
  int C, c0, c1, lo, hi, slot0;
  bool band;
  std::size_t row;
  float *h, *b;
  float re, rd;
  bool s_last = false;

  POND_KERNEL_INLINE RowSprings(const StepView& view, int i, int block0, int block1, float* scratch,
                                int hs, int cur)
      : v(view), C(view.cols), c0(block0), c1(block1), lo(block0 > 0 ? block0 - 1 : 0),
        hi(block1 - 1 < view.cols - 2 ? block1 - 1 : view.cols - 2), slot0(1 - block0),
        band(i + 1 < view.rows), row(static_cast<std::size_t>(i) * view.cols),
        h(scratch + h_row(hs) * kSlots), b(scratch + band_row(cur) * kSlots), re(view.k.rest_edge),
        rd(view.k.rest_diag) {
    if (!band) fill_band(scratch, cur, c1 - c0, -0.0f);
  }

  // The four springs of a cell corner from the cell's four nodes, each loaded once. S is also
  // evaluated at index c0-1 (slot 0, never read). S(C-1), the one spring without a right
  // neighbour, comes from the last chunk's right column pair when that chunk overlaps the one
  // before it (S(j+1) from e and ue instead of S(j) from a and u: the same spring, the same
  // inputs), else on its own in finish(). (S(c1) of an inner block, also computed then, is never
  // read.) Without a row below, only H.
  template <class V, bool Shifted>
  POND_KERNEL_INLINE void operator()(int j) {
    using K = StepKernel<V, Steps>;
    const std::size_t n = row + j;
    const int s = j + slot0;
    if (band) {
      const auto a = K::load(v, n), e = K::load(v, n + 1), u = K::load(v, n + C),
                 ue = K::load(v, n + C + 1);
      const typename K::Spring sp[4] = {
          K::template vec<1, 0>(a, e, re, h + s),  // H:  (i,j) -> (i,j+1)
          // S:  (i,j) -> (i+1,j), or S(j+1) in a shifted last chunk
          Shifted ? K::template vec<0, 1>(e, ue, re, b + kBandS * kSlots + s + 1)
                  : K::template vec<0, 1>(a, u, re, b + kBandS * kSlots + s),
          K::template vec<1, 1>(a, ue, rd, b + kBandD1 * kSlots + s),   // D1: (i,j) -> (i+1,j+1)
          K::template vec<-1, 1>(e, u, rd, b + kBandD2 * kSlots + s)};  // D2: (i,j+1) -> (i+1,j)
      K::springs(sp);
      if constexpr (Shifted) s_last = true;
    } else {
      K::template spring<1, 0>(K::load(v, n), K::load(v, n + 1), re, h + s);
    }
  }

  POND_KERNEL_INLINE void finish() {
    if (band && c1 == C && !s_last) {
      using K = StepKernel<WideScalar, Steps>;
      const std::size_t n = row + C - 1;
      K::template spring<0, 1>(K::load(v, n), K::load(v, n + C), re,
                               b + kBandS * kSlots + C - 1 + slot0);
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
};

template <class W, int Steps>
POND_KERNEL_INLINE void block_springs(const StepView& v, int i, int c0, int c1, float* scratch,
                                      int hs, int cur) {
  RowSprings<W, Steps> sp(v, i, c0, c1, scratch, hs, cur);
  for_chunks<W>(sp.lo, sp.hi + 1, sp);
  sp.finish();
}

// Sums the spring terms of nodes [j, j + width) of row i in canonical order and integrates them.
// Returns `check` plus the new velocity components (non-finite iff the step blew up).
template <class W>
POND_KERNEL_INLINE typename W::F integrate_at(const StepView& v, int i, int j, int c0,
                                              const float* scratch, int hs, int below, int above,
                                              typename W::F check) {
  using F = typename W::F;
  const std::size_t n = static_cast<std::size_t>(i) * v.cols + j;
  const int s = j - c0 + 1;  // slot of column j
  const float* h = scratch + h_row(hs) * kSlots + s;
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

// The integration of row i of a block, chunk by chunk, with its blow-up check per chunk width.
template <class W>
struct RowIntegrate {
  using H = typename W::Half;
  const StepView& v;
  int i = 0, c0 = 0, hs = 0, below = 0, above = 0;
  const float* scratch = nullptr;
  typename W::F check = W::set1(0.0f);
  typename H::F half_check = H::set1(0.0f);
  float tail_check = 0.0f;

  explicit RowIntegrate(const StepView& view) : v(view) {}
  template <class V, bool>
  POND_KERNEL_INLINE void operator()(int j) {
    if constexpr (V::width == W::width && W::width > 1)
      check = integrate_at<W>(v, i, j, c0, scratch, hs, below, above, check);
    else if constexpr (V::width == H::width && H::width > 1)
      half_check = integrate_at<H>(v, i, j, c0, scratch, hs, below, above, half_check);
    else
      tail_check = integrate_at<WideScalar>(v, i, j, c0, scratch, hs, below, above, tail_check);
  }
  float sum() const { return W::sum_lanes(check) + H::sum_lanes(half_check) + tail_check; }
};

// One substep for rows [r0, r1), block by block. Returns the sum of the new velocity components
// of those rows (non-finite iff some velocity is non-finite or astronomically large).
//
// The springs run one row ahead of the integration, so the spring rows row i reads were stored a
// whole row earlier (a load that straddles two stores still in flight, as the j-1 terms do, cannot
// be forwarded from them and waits).
template <class W, int Steps>
float step_rows(const StepView& v, int r0, int r1, float* scratch_base) {
  RowIntegrate<W> in(v);
  for (int c0 = 0; c0 < v.cols; c0 += kBlockCols) {
    const int c1 = c0 + kBlockCols < v.cols ? c0 + kBlockCols : v.cols;
    // The spring chunks start at slot 1 (first block) or 0: shift the slots so that it is 64-byte
    // aligned (scratch and kSlots are), making the chunks' stores aligned where they do not
    // overlap: unaligned vector stores are markedly slower on Zen 4 (docs/perf.md).
    float* const scratch = scratch_base + (c0 == 0 ? kSlotAlign - 1 : 0);
    int below = 0, above = 1, ahead = 2;  // bands of rows i-1, i, i+1
    int hs = 0;                           // H row of row i (row i+1's is 1 - hs)
    if (r0 == 0) {
      fill_band(scratch, below, c1 - c0, +0.0f);  // no row -1: lower-band terms subtract +0
    } else {
      block_springs<W, Steps>(v, r0 - 1, c0, c1, scratch, 1 - hs, below);  // its H is not used
    }
    block_springs<W, Steps>(v, r0, c0, c1, scratch, hs, above);
    in.c0 = c0;
    in.scratch = scratch;
    for (int i = r0; i < r1; ++i) {
      in.i = i;
      in.hs = hs;
      in.below = below;
      in.above = above;
      if (i + 1 < r1) block_springs<W, Steps>(v, i + 1, c0, c1, scratch, 1 - hs, ahead);
      for_chunks<W>(c0, c1, in);
      const int done = below;
      below = above;
      above = ahead;
      ahead = done;
      hs = 1 - hs;
    }
  }
  return in.sum();
}

}  // namespace POND_ISA
}  // namespace pond::sim
