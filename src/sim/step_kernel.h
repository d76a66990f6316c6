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
//  - The force term of spring a->b on a is  (x_b - x_a) * (1 - L * rsqrt(l2)),
//    l2 = (dx*dx + dy*dy) + dz*dz,  rsqrt = seed + Newton steps (shared/exact_math.h). On b it is
//    the exact negation (IEEE subtraction and multiplication are sign-symmetric), so evaluating it
//    from either end (as the GPU does) gives the same bits.
//  - CANONICAL SUMMATION ORDER (the GPU shader follows it): node (i,j) sums its neighbour terms,
//    starting from -0.0, in the order
//        (i,j-1) (i,j+1) (i-1,j) (i+1,j) (i-1,j-1) (i+1,j+1) (i-1,j+1) (i+1,j-1).
//    A missing neighbour (grid border) is skipped; here that is an addition of -0 or a subtraction
//    of +0, both the exact identity on every float including signed zeros.
//  - Integration (symplectic Euler, model.h):  v' = v + (G*kc - v*kd);  constrained velocity
//    components become +0;  x' = x + v'*dt.
#include <cstddef>
#include <cstdint>
#include <utility>

#include "shared/exact_math.h"
#include "sim/isa_namespace.h"
#include "sim/step_view.h"
#include "sim/wide_scalar.h"

namespace pond::sim {
inline namespace POND_ISA {

template <class W>
struct StepKernel {
  using F = typename W::F;

  static F rsqrt(F x, int steps) {
    const F half_x = W::mul(x, W::set1(0.5f));
    F y = W::rsqrt_seed(x, shared::kRsqrtMagic);
    for (int k = 0; k < steps; ++k) {
      F t = W::mul(y, y);
      t = W::mul(t, half_x);
      t = W::sub(W::set1(1.5f), t);
      y = W::mul(y, t);
    }
    return y;
  }

  // The term of spring a->b on node a, stored at out[c][slot] for components c = x, y, z.
  static void spring(const float* const a[3], const float* const b[3], std::size_t na,
                     std::size_t nb, float rest, int steps, float* const out[3], int slot) {
    const F dx = W::sub(W::load(b[0] + nb), W::load(a[0] + na));
    const F dy = W::sub(W::load(b[1] + nb), W::load(a[1] + na));
    const F dz = W::sub(W::load(b[2] + nb), W::load(a[2] + na));
    const F l2 = W::add(W::add(W::mul(dx, dx), W::mul(dy, dy)), W::mul(dz, dz));
    const F f = W::sub(W::set1(1.0f), W::mul(W::set1(rest), rsqrt(l2, steps)));
    W::store(out[0] + slot, W::mul(dx, f));
    W::store(out[1] + slot, W::mul(dy, f));
    W::store(out[2] + slot, W::mul(dz, f));
  }

  // Springs of row i for columns [j, j + W::width): H, and S, D1, D2 to row i+1 if `band`.
  static void springs_at(const StepView& v, int i, int j, bool band, const SpringRows& r, int cur) {
    const float* const p[3] = {v.x, v.y, v.z};
    const std::size_t n = static_cast<std::size_t>(i) * v.cols + j;
    const std::size_t up = n + v.cols;
    const int slot = j + 1;
    spring(p, p, n, n + 1, v.k.rest_edge, v.k.rsqrt_steps, r.h, slot);
    if (!band) return;
    spring(p, p, n, up, v.k.rest_edge, v.k.rsqrt_steps, r.s[cur], slot);
    spring(p, p, n, up + 1, v.k.rest_diag, v.k.rsqrt_steps, r.d1[cur], slot);
    spring(p, p, n + 1, up, v.k.rest_diag, v.k.rsqrt_steps, r.d2[cur], slot);
  }
};

// Fills a band slot range with a signed zero: +0 where the band is subtracted, -0 where added.
inline void fill_band(const SpringRows& r, int band, int slots, float value) {
  for (int c = 0; c < 3; ++c)
    for (int s = 0; s <= slots; ++s) r.s[band][c][s] = r.d1[band][c][s] = r.d2[band][c][s] = value;
}

// Computes H of row i and, when i + 1 < rows, the band to row i+1 into band `cur`; otherwise fills
// band `cur` with -0 (it is only ever added).
template <class W>
void compute_row_springs(const StepView& v, int i, const SpringRows& r, int cur) {
  using K = StepKernel<W>;
  using S = StepKernel<WideScalar>;
  const bool band = i + 1 < v.rows;
  const int C = v.cols;
  int j = 0;
  for (; j + W::width <= C - 1; j += W::width) K::springs_at(v, i, j, band, r, cur);
  for (; j < C - 1; ++j) S::springs_at(v, i, j, band, r, cur);
  for (int c = 0; c < 3; ++c) {
    r.h[c][0] = +0.0f;  // index -1: subtracted by node 0
    r.h[c][C] = -0.0f;  // index C-1: added by node C-1
  }
  if (!band) {
    fill_band(r, cur, C, -0.0f);
    return;
  }
  {  // S(C-1), the one spring of the band without a right neighbour
    const float* const p[3] = {v.x, v.y, v.z};
    const std::size_t n = static_cast<std::size_t>(i) * C + (C - 1);
    S::spring(p, p, n, n + C, v.k.rest_edge, v.k.rsqrt_steps, r.s[cur], C);
  }
  for (int c = 0; c < 3; ++c) {
    r.d1[cur][c][0] = +0.0f;  // only subtracted (as the lower band, by node 0)
    r.d1[cur][c][C] = -0.0f;  // only added (as the upper band, by node C-1)
    r.d2[cur][c][0] = -0.0f;  // only added (as the upper band, by node 0)
    r.d2[cur][c][C] = +0.0f;  // only subtracted (as the lower band, by node C-1)
  }
}

// Sums the terms of nodes [j, j + width) of row i in canonical order and integrates them.
// Returns the sum of the new velocity components, whose finiteness tells whether the step blew up.
template <class W>
typename W::F integrate_at(const StepView& v, int i, int j, const SpringRows& r, int below,
                           int above, typename W::F check) {
  using F = typename W::F;
  const int s = j + 1;  // slot of index j
  const std::size_t n = static_cast<std::size_t>(i) * v.cols + j;
  const F kc = W::set1(v.k.kc), kd = W::set1(v.k.kd), dt = W::set1(v.k.dt);
  const typename W::M free_h = W::kind_below(v.kinds + n, 1);  // free nodes move horizontally
  const typename W::M free_v = W::kind_below(v.kinds + n, 2);  // free and vertical nodes move in y
  const float* const pos[3] = {v.x, v.y, v.z};
  const float* const vel[3] = {v.vx, v.vy, v.vz};
  float* const opos[3] = {v.ox, v.oy, v.oz};
  float* const ovel[3] = {v.ovx, v.ovy, v.ovz};
  F vsum[3];
  for (int c = 0; c < 3; ++c) {
    F g = W::neg(W::load(r.h[c] + s - 1));          // (i, j-1)
    g = W::add(g, W::load(r.h[c] + s));             // (i, j+1)
    g = W::sub(g, W::load(r.s[below][c] + s));      // (i-1, j)
    g = W::add(g, W::load(r.s[above][c] + s));      // (i+1, j)
    g = W::sub(g, W::load(r.d1[below][c] + s - 1)); // (i-1, j-1)
    g = W::add(g, W::load(r.d1[above][c] + s));     // (i+1, j+1)
    g = W::sub(g, W::load(r.d2[below][c] + s));     // (i-1, j+1)
    g = W::add(g, W::load(r.d2[above][c] + s - 1)); // (i+1, j-1)
    const F vel0 = W::load(vel[c] + n);
    F v1 = W::add(vel0, W::sub(W::mul(g, kc), W::mul(vel0, kd)));
    v1 = W::keep(c == 1 ? free_v : free_h, v1);
    W::store(ovel[c] + n, v1);
    W::store(opos[c] + n, W::add(W::load(pos[c] + n), W::mul(v1, dt)));
    vsum[c] = v1;
  }
  return W::add(check, W::add(W::add(vsum[0], vsum[1]), vsum[2]));
}

// One substep for rows [r0, r1). Returns the sum of all new velocity components of those rows
// (non-finite iff some velocity is non-finite or astronomically large).
template <class W>
float step_rows(const StepView& v, int r0, int r1, const SpringRows& r) {
  using F = typename W::F;
  int below = 0, above = 1;
  if (r0 == 0) {
    fill_band(r, below, v.cols, +0.0f);  // no row -1: every lower-band term is subtracted +0
  } else {
    compute_row_springs<W>(v, r0 - 1, r, below);
  }
  F check = W::set1(0.0f);
  float tail_check = 0.0f;
  for (int i = r0; i < r1; ++i) {
    compute_row_springs<W>(v, i, r, above);
    int j = 0;
    for (; j + W::width <= v.cols; j += W::width) check = integrate_at<W>(v, i, j, r, below, above, check);
    for (; j < v.cols; ++j) tail_check = integrate_at<WideScalar>(v, i, j, r, below, above, tail_check);
    std::swap(below, above);
  }
  return W::sum_lanes(check) + tail_check;
}

}  // namespace POND_ISA
}  // namespace pond::sim
