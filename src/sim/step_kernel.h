#pragma once
// One substep of the water grid over a range of rows, written once against the wide-float
// operation table W (wide_scalar.h, wide_sse2.h, wide_avx2.h, wide_avx512.h, wide_neon.h). Instantiated per
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
//  - Integration (semi-implicit Euler, model.h):  v' = v + (G*kc - v*kd);  constrained velocity
//    components become +0;  u' = u + v'*dt.
#include <cstddef>
#include <cstdint>
#include <utility>

#include "shared/exact_math.h"
#include "sim/backends.h"
#include "sim/chunks.h"
#include "sim/isa_namespace.h"
#include "sim/step_view.h"
#include "sim/tile_kernel.h"
#include "sim/wide_scalar.h"

namespace pond::sim {
inline namespace POND_ISA {

// Offsets of the spring rows in the scratch (see step_view.h): two rows of H springs (x, y, z
// each; row i's and row i+1's) and three bands of S, D1, D2 (x, y, z each; rows i-1, i, i+1).
POND_KERNEL_INLINE constexpr int h_row(int h_index) { return 3 * h_index; }
POND_KERNEL_INLINE constexpr int band_row(int band) { return 6 + 9 * band; }
inline constexpr int kBandS = 0, kBandD1 = 3, kBandD2 = 6;

// Steps: the Newton steps of the reciprocal square root, a compile-time constant so the four
// springs' iterations unroll and interleave.
template <class W, int Steps>
struct StepKernel {
  using F = typename W::F;

  struct Node {
    F x, y, z;
  };
  POND_KERNEL_INLINE static Node load(const StepView& view, std::size_t n) {
    return {W::load(view.ux + n), W::load(view.uy + n), W::load(view.uz + n)};
  }

  // A spring a->b: its vector (b at column offset DJ and row offset DI from a), rest length and
  // the three spring rows at `out` (x, y, z) its term on a goes to.
  struct Spring {
    F dx, dy, dz;
    float rest;
    float* out;
  };
  template <int DJ, int DI>
  POND_KERNEL_INLINE static Spring make_spring(const Node& a, const Node& b, float rest,
                                               float* out) {
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
  POND_KERNEL_INLINE static void spring_terms(const Spring (&springs)[K]) {
    F l2[K], inv_len[K];
    for (int k = 0; k < K; ++k)
      l2[k] =
          W::add(W::add(W::mul(springs[k].dx, springs[k].dx), W::mul(springs[k].dy, springs[k].dy)),
                 W::mul(springs[k].dz, springs[k].dz));
    rsqrt_n(l2, inv_len);
    for (int k = 0; k < K; ++k) {
      const F scale = W::sub(W::set1(1.0f), W::mul(W::set1(springs[k].rest), inv_len[k]));
      W::store(springs[k].out, W::mul(springs[k].dx, scale));
      W::store(springs[k].out + kSlots, W::mul(springs[k].dy, scale));
      W::store(springs[k].out + 2 * kSlots, W::mul(springs[k].dz, scale));
    }
  }

  // The term of spring a->b on node a, b at column offset DJ and row offset DI from a, stored in
  // the three spring rows at `out` (x, y, z).
  template <int DJ, int DI>
  POND_KERNEL_INLINE static void spring_term(const Node& a, const Node& b, float rest, float* out) {
    const Spring one[1] = {make_spring<DJ, DI>(a, b, rest, out)};
    spring_terms<1>(one);
  }
};

// Fills slots [0, last_slot] of a band with a signed zero: +0 where the band is subtracted (below
// the row), -0 where it is added (above): either way the exact identity.
POND_KERNEL_INLINE void fill_band(float* scratch, int band, int last_slot, float zero) {
  float* band_springs = scratch + band_row(band) * kSlots;
  for (int spring_row = 0; spring_row < 9; ++spring_row)
    for (int slot = 0; slot <= last_slot; ++slot) band_springs[spring_row * kSlots + slot] = zero;
}

// The springs of row i that the block of columns [block_begin, block_end) needs: H, D1, D2 at
// column indices [first_spring, last_spring] = [max(block_begin-1, 0), min(block_end-1, cols-2)]
// into H row `h_index` and band `band`, S at [block_begin, block_end) into band `band`; without a
// row i+1, band `band` becomes -0. Missing indices -1 and cols-1 get the signed zero that makes
// their use an identity: for_chunks over [first_spring, last_spring] with this object, then
// finish().
template <class W, int Steps>
struct RowSprings {
  const StepView& view;
  int cols, block_begin, block_end, first_spring, last_spring;
  int slot_offset;  // the slot of column index j is j + slot_offset
  bool has_next_row;
  std::size_t row_start;  // node (i, 0)
  float* h_springs;       // slot 0 of H row `h_index` (its x row; y, z follow)
  float* band_springs;    // slot 0 of band `band` (its S x row; the other eight follow)
  float rest_edge, rest_diag;
  bool last_s_done = false;  // a shifted last chunk computed S(last_spring + 1)

  POND_KERNEL_INLINE RowSprings(const StepView& step_view, int i, int begin_col, int end_col,
                                float* scratch, int h_index, int band)
      : view(step_view), cols(step_view.cols), block_begin(begin_col), block_end(end_col),
        first_spring(begin_col > 0 ? begin_col - 1 : 0),
        last_spring(end_col - 1 < step_view.cols - 2 ? end_col - 1 : step_view.cols - 2),
        slot_offset(1 - begin_col), has_next_row(i + 1 < step_view.rows),
        row_start(static_cast<std::size_t>(i) * step_view.cols),
        h_springs(scratch + h_row(h_index) * kSlots),
        band_springs(scratch + band_row(band) * kSlots), rest_edge(step_view.k.rest_edge),
        rest_diag(step_view.k.rest_diag) {
    if (!has_next_row) fill_band(scratch, band, block_end - block_begin, -0.0f);
  }

  // The four springs of a cell corner from the cell's four nodes, each loaded once. S is also
  // evaluated at index block_begin-1 (slot 0, never read). S(cols-1), the one spring without a
  // right neighbour, comes from the last chunk's right column pair when that chunk overlaps the
  // one before it (S(j+1) from `right` and `up_right` instead of S(j) from `here` and `up`: the
  // same spring, the same inputs), else on its own in finish(). (S(block_end) of an inner block,
  // also computed then, is never read.) Without a row i+1, only H.
  template <class V, bool Shifted>
  POND_KERNEL_INLINE void operator()(int j) {
    using Kernel = StepKernel<V, Steps>;
    const std::size_t n = row_start + j;
    const int slot = j + slot_offset;
    if (has_next_row) {  // the cell's nodes (i,j), (i,j+1), (i+1,j), (i+1,j+1)
      const auto here = Kernel::load(view, n), right = Kernel::load(view, n + 1),
                 up = Kernel::load(view, n + cols), up_right = Kernel::load(view, n + cols + 1);
      const typename Kernel::Spring cell[4] = {
          // H:  (i,j) -> (i,j+1)
          Kernel::template make_spring<1, 0>(here, right, rest_edge, h_springs + slot),
          // S:  (i,j) -> (i+1,j), or S(j+1) in a shifted last chunk
          Shifted ? Kernel::template make_spring<0, 1>(right, up_right, rest_edge,
                                                       band_springs + kBandS * kSlots + slot + 1)
                  : Kernel::template make_spring<0, 1>(here, up, rest_edge,
                                                       band_springs + kBandS * kSlots + slot),
          // D1: (i,j) -> (i+1,j+1)
          Kernel::template make_spring<1, 1>(here, up_right, rest_diag,
                                             band_springs + kBandD1 * kSlots + slot),
          // D2: (i,j+1) -> (i+1,j)
          Kernel::template make_spring<-1, 1>(right, up, rest_diag,
                                              band_springs + kBandD2 * kSlots + slot)};
      Kernel::spring_terms(cell);
      if constexpr (Shifted) last_s_done = true;
    } else {
      Kernel::template spring_term<1, 0>(Kernel::load(view, n), Kernel::load(view, n + 1),
                                         rest_edge, h_springs + slot);
    }
  }

  POND_KERNEL_INLINE void finish() {
    if (has_next_row && block_end == cols && !last_s_done) {
      using Kernel = StepKernel<WideScalar, Steps>;
      const std::size_t n = row_start + cols - 1;
      Kernel::template spring_term<0, 1>(Kernel::load(view, n), Kernel::load(view, n + cols),
                                         rest_edge,
                                         band_springs + kBandS * kSlots + cols - 1 + slot_offset);
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (block_begin == 0) {  // index -1 is slot 0
        h_springs[axis * kSlots] = +0.0f;  // only subtracted (by node 0)
        if (has_next_row) {
          band_springs[(kBandD1 + axis) * kSlots] = +0.0f;  // only subtracted (as the lower band)
          band_springs[(kBandD2 + axis) * kSlots] = -0.0f;  // only added (as the upper band)
        }
      }
      if (block_end == cols) {
        const int slot = cols - 1 + slot_offset;
        h_springs[axis * kSlots + slot] = -0.0f;  // index cols-1: only added (by node cols-1)
        if (has_next_row) {
          band_springs[(kBandD1 + axis) * kSlots + slot] = -0.0f;  // only added (upper band)
          band_springs[(kBandD2 + axis) * kSlots + slot] = +0.0f;  // only subtracted (lower band)
        }
      }
    }
  }
};

template <class W, int Steps>
POND_KERNEL_INLINE void block_springs(const StepView& view, int i, int block_begin, int block_end,
                                      float* scratch, int h_index, int band) {
  RowSprings<W, Steps> row_springs(view, i, block_begin, block_end, scratch, h_index, band);
  for_chunks<W>(row_springs.first_spring, row_springs.last_spring + 1, row_springs);
  row_springs.finish();
}

// Sums the spring terms of nodes [j, j + width) of row i in canonical order and integrates them.
// Returns `check` plus the new velocity components (non-finite iff the step blew up). With Reach,
// `reach` also takes the largest |u'x| and |u'z| (the bodies' contact needs that bound).
template <class W, bool Reach>
POND_KERNEL_INLINE typename W::F integrate_at(const StepView& view, int i, int j, int block_begin,
                                              const float* scratch, int h_index, int below,
                                              int above, typename W::F check, typename W::F& reach) {
  using F = typename W::F;
  const std::size_t n = static_cast<std::size_t>(i) * view.cols + j;
  const int slot = j - block_begin + 1;  // slot of column j
  // Column j's slot in the H row and in the bands of rows i-1 (below) and i (above).
  const float* h_springs = scratch + h_row(h_index) * kSlots + slot;
  const float* band_below = scratch + band_row(below) * kSlots + slot;
  const float* band_above = scratch + band_row(above) * kSlots + slot;
  const F kc = W::set1(view.k.kc), kd = W::set1(view.k.kd), dt = W::set1(view.k.dt);
  // Free nodes move horizontally; free and vertical nodes move in y.
  const typename W::M free_h = W::kind_below(view.kinds + n, 1);
  const typename W::M free_v = W::kind_below(view.kinds + n, 2);
  const float* const pos[3] = {view.ux, view.uy, view.uz};
  const float* const vel[3] = {view.vx, view.vy, view.vz};
  float* const out_pos[3] = {view.oux, view.ouy, view.ouz};
  float* const out_vel[3] = {view.ovx, view.ovy, view.ovz};
  for (int axis = 0; axis < 3; ++axis) {
    const int axis_row = axis * kSlots;  // the axis's row in the H row and in S, D1, D2
    F sum = W::neg(W::load(h_springs + axis_row - 1));                         // (i, j-1)
    sum = W::add(sum, W::load(h_springs + axis_row));                          // (i, j+1)
    sum = W::sub(sum, W::load(band_below + kBandS * kSlots + axis_row));       // (i-1, j)
    sum = W::add(sum, W::load(band_above + kBandS * kSlots + axis_row));       // (i+1, j)
    sum = W::sub(sum, W::load(band_below + kBandD1 * kSlots + axis_row - 1));  // (i-1, j-1)
    sum = W::add(sum, W::load(band_above + kBandD1 * kSlots + axis_row));      // (i+1, j+1)
    sum = W::sub(sum, W::load(band_below + kBandD2 * kSlots + axis_row));      // (i-1, j+1)
    sum = W::add(sum, W::load(band_above + kBandD2 * kSlots + axis_row - 1));  // (i+1, j-1)
    const F old_v = W::load(vel[axis] + n);
    // v' = v + (G*kc - v*kd), G = sum; +0 where constrained
    F new_v = W::add(old_v, W::sub(W::mul(sum, kc), W::mul(old_v, kd)));
    new_v = W::keep(axis == 1 ? free_v : free_h, new_v);
    W::store(out_vel[axis] + n, new_v);
    const F new_u = W::add(W::load(pos[axis] + n), W::mul(new_v, dt));
    W::store(out_pos[axis] + n, new_u);
    if constexpr (Reach)
      if (axis != 1) reach = W::max_abs(reach, new_u);
    check = W::add(check, new_v);
  }
  return check;
}

// The largest lane of v (the reach's, once per substep and part).
template <class W>
float max_lanes(typename W::F v) {
  alignas(64) float lanes[W::width];
  W::store(lanes, v);
  float m = lanes[0];
  for (float x : lanes) m = x > m ? x : m;
  return m;
}

// The integration of row i of a block, chunk by chunk, with its blow-up check (and the reach of
// the horizontal displacements) per chunk width.
template <class W, bool Reach>
struct RowIntegrate {
  using Half = typename W::Half;
  const StepView& view;
  int i = 0, block_begin = 0, h_index = 0, below = 0, above = 0;
  const float* scratch = nullptr;
  typename W::F check = W::set1(0.0f);
  typename Half::F half_check = Half::set1(0.0f);
  float tail_check = 0.0f;
  typename W::F reach = W::set1(0.0f);
  typename Half::F half_reach = Half::set1(0.0f);
  float tail_reach = 0.0f;

  explicit RowIntegrate(const StepView& step_view) : view(step_view) {}
  template <class V, bool>
  POND_KERNEL_INLINE void operator()(int j) {
    if constexpr (V::width == W::width && W::width > 1)
      check = integrate_at<W, Reach>(view, i, j, block_begin, scratch, h_index, below, above, check, reach);
    else if constexpr (V::width == Half::width && Half::width > 1)
      half_check = integrate_at<Half, Reach>(view, i, j, block_begin, scratch, h_index, below, above,
                                             half_check, half_reach);
    else
      tail_check = integrate_at<WideScalar, Reach>(view, i, j, block_begin, scratch, h_index, below,
                                                   above, tail_check, tail_reach);
  }
  float sum() const { return W::sum_lanes(check) + Half::sum_lanes(half_check) + tail_check; }
  float max_reach() const {
    const float a = max_lanes<W>(reach), b = max_lanes<Half>(half_reach);
    const float m = a > b ? a : b;
    return tail_reach > m ? tail_reach : m;
  }
};

// One substep for rows [row_begin, row_end), block by block. Returns the sum of the new velocity
// components of those rows (non-finite iff some velocity is non-finite or astronomically large).
// With Reach it also stores in *reach the largest |u'x|, |u'z| of those rows (shared/bodies.h);
// with Tiles, it emits their tile bounds to *tiles (tile_kernel.h).
//
// The springs run one row ahead of the integration, so the spring rows row i reads were stored a
// whole row earlier (a load that straddles two stores still in flight, as the j-1 terms do, cannot
// be forwarded from them and waits).
template <class W, int Steps, bool Reach, bool Tiles>
float step_rows(const StepView& view, int row_begin, int row_end, float* scratch_base, float* reach,
                TileSink* tiles) {
  RowIntegrate<W, Reach> integrate(view);
  const TileGrid tile_grid = Tiles ? TileGrid(view.rows, view.cols) : TileGrid();
  for (int block_begin = 0; block_begin < view.cols; block_begin += kBlockCols) {
    const int block_end =
        block_begin + kBlockCols < view.cols ? block_begin + kBlockCols : view.cols;
    // The spring chunks start at slot 1 (first block) or 0: shift the slots so that it is 64-byte
    // aligned (scratch and kSlots are), making the chunks' stores aligned where they do not
    // overlap: unaligned vector stores are markedly slower on Zen 4 (docs/perf.md).
    float* const scratch = scratch_base + (block_begin == 0 ? kSlotAlign - 1 : 0);
    int below = 0, above = 1, ahead = 2;  // bands of rows i-1, i, i+1
    int h_index = 0;                      // H row of row i (row i+1's is 1 - h_index)
    if (row_begin == 0) {
      // No row -1: the lower-band terms subtract +0.
      fill_band(scratch, below, block_end - block_begin, +0.0f);
    } else {
      block_springs<W, Steps>(view, row_begin - 1, block_begin, block_end, scratch, 1 - h_index,
                              below);  // its H is not used
    }
    block_springs<W, Steps>(view, row_begin, block_begin, block_end, scratch, h_index, above);
    integrate.block_begin = block_begin;
    integrate.scratch = scratch;
    for (int i = row_begin; i < row_end; ++i) {
      integrate.i = i;
      integrate.h_index = h_index;
      integrate.below = below;
      integrate.above = above;
      if (i + 1 < row_end)
        block_springs<W, Steps>(view, i + 1, block_begin, block_end, scratch, 1 - h_index, ahead);
      for_chunks<W>(block_begin, block_end, integrate);
      if constexpr (Tiles) {
        const TileRowEvents events = tile_row_events(i, row_end, pass_rows(block_end - block_begin));
        if (events.any()) emit_tile_rows<W>(view, tile_grid, events, i, row_begin, block_begin, block_end, *tiles);
      }
      const int recycled = below;
      below = above;
      above = ahead;
      ahead = recycled;
      h_index = 1 - h_index;
    }
  }
  if constexpr (Reach) *reach = integrate.max_reach();
  return integrate.sum();
}

// The kernel of backend W for a number of Newton steps, tracking the reach or not, emitting the
// tile bounds or not.
template <class W, int Steps>
StepRowsFn step_rows_with(bool reach, bool tiles) {
  if (reach) return tiles ? &step_rows<W, Steps, true, true> : &step_rows<W, Steps, true, false>;
  return tiles ? &step_rows<W, Steps, false, true> : &step_rows<W, Steps, false, false>;
}
template <class W>
StepRowsFn step_rows_of(int rsqrt_steps, bool reach, bool tiles) {
  if (rsqrt_steps == shared::kRsqrtStepsFast) return step_rows_with<W, shared::kRsqrtStepsFast>(reach, tiles);
  return step_rows_with<W, shared::kRsqrtStepsExact>(reach, tiles);
}

}  // namespace POND_ISA
}  // namespace pond::sim
