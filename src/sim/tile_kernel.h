#pragma once
// The tile bounds (shared/tile_bounds.h) as a by-product of the step kernel (step_kernel.h): the
// new displacements the kernel has just written in a block of columns are read back, while still
// in the core's caches, into each column's bounds over the tile row (TileSink::columns): in a
// narrow block once a tile row, down each group of columns; in a wide one every four rows, along
// them (pass_rows()). After the row that ends the tile row, its tiles come from those and that row.
// Min and max are exact: the tiles' values do not depend on the width or the order of the
// operations, only the sign of a zero bound may, and the solver's merge makes every zero +0.
#include <cstddef>

#include "sim/chunks.h"
#include "sim/isa_namespace.h"
#include "sim/step_view.h"
#include "sim/tile_bounds.h"
#include "sim/wide_scalar.h"
#include "sim/wide_baseline.h"

namespace pond::sim {
inline namespace POND_ISA {

inline constexpr int kTileCells = POND_TILE_CELLS;
// Vectors of columns a pass keeps the bounds of in registers (two each): as many as the registers
// leave room for, so each row's read is several cache lines long.
template <class V>
inline constexpr int kPassGroup = V::width == 16 ? 8 : 4;
// Rows a pass over a wide block reads (pass_rows()), in registers before the columns' bounds take
// them in.
inline constexpr int kWidePassRows = 4;

// The wide table the bounds use with backend W: W's own, and the target's baseline (SSE2, NEON:
// wide_baseline.h) for the scalar backend, whose one-lane table would keep 32 bounds per tile.
template <class W>
struct BoundsWide {
  using type = W;
};
template <>
struct BoundsWide<WideScalar> {
  using type = WideBaseline;
};

// The bounds of columns [j, j + K * V::width) (`column` is column j's in TileSink::columns) over
// the new displacements of rows [row0, row1]: row by row, in registers.
template <class V, int K>
POND_KERNEL_INLINE void group_bounds(const StepView& view, int row0, int row1, int j, float* column) {
  const float* const out[3] = {view.oux, view.ouy, view.ouz};
  const std::size_t cols = static_cast<std::size_t>(view.cols);
  for (int axis = 0; axis < 3; ++axis) {
    const float* u = out[axis] + row0 * cols + j;
    typename V::F lo[K], hi[K];
    for (int k = 0; k < K; ++k) lo[k] = hi[k] = V::load(u + k * V::width);
    for (int i = row0 + 1; i <= row1; ++i) {
      u += cols;
      for (int k = 0; k < K; ++k) {
        const typename V::F x = V::load(u + k * V::width);
        lo[k] = V::min_of(x, lo[k]);
        hi[k] = V::max_of(x, hi[k]);
      }
    }
    for (int k = 0; k < K; ++k) {
      V::store(column + axis * kColumnsPitch + k * V::width, lo[k]);
      V::store(column + (3 + axis) * kColumnsPitch + k * V::width, hi[k]);
    }
  }
}

// Rows [row, row + R) of one axis (`u` at the block's first column, rows `cols` apart) widen the
// columns' least and greatest (`lo`, `hi`; set, not widened, when `first`), row by row along the
// block, so each row is read front to back where the prefetchers follow it.
template <class V, int R>
POND_KERNEL_INLINE void rows_into_columns(const float* u, std::size_t cols, int width, float* lo, float* hi,
                                          bool first) {
  int j = 0;
  for (; width - j >= V::width; j += V::width) {
    typename V::F l = V::load(u + j), h = l;
    for (int r = 1; r < R; ++r) {
      const typename V::F x = V::load(u + r * cols + j);
      l = V::min_of(x, l);
      h = V::max_of(x, h);
    }
    if (!first) {
      l = V::min_of(V::load(lo + j), l);
      h = V::max_of(V::load(hi + j), h);
    }
    V::store(lo + j, l);
    V::store(hi + j, h);
  }
  for (; j < width; ++j) {
    float l = u[j], h = l;
    for (int r = 1; r < R; ++r) {
      l = WideScalar::min_of(u[r * cols + j], l);
      h = WideScalar::max_of(u[r * cols + j], h);
    }
    lo[j] = first ? l : WideScalar::min_of(lo[j], l);
    hi[j] = first ? h : WideScalar::max_of(hi[j], h);
  }
}

// The columns' bounds of a narrow block over rows [row0, row1] (all integrated): each group of
// columns down the rows, in registers.
template <class V>
POND_KERNEL_INLINE void narrow_block_bounds(const StepView& view, int row0, int row1, int block_begin,
                                            int block_end, float* columns) {
  int j = block_begin;
  for (; block_end - j >= kPassGroup<V> * V::width; j += kPassGroup<V> * V::width)
    group_bounds<V, kPassGroup<V>>(view, row0, row1, j, columns + (j - block_begin));
  for (; block_end - j >= V::width; j += V::width) group_bounds<V, 1>(view, row0, row1, j, columns + (j - block_begin));
  for (; j < block_end; ++j) group_bounds<WideScalar, 1>(view, row0, row1, j, columns + (j - block_begin));
}

// The columns' bounds of a wide block widened by rows [row0, row1] (all integrated; set, not
// widened, when `fresh`): along the rows, kWidePassRows at a time.
template <class V>
POND_KERNEL_INLINE void wide_block_bounds(const StepView& view, int row0, int row1, int block_begin, int block_end,
                                          float* columns, bool fresh) {
  constexpr int kRows = kWidePassRows;
  const float* const out[3] = {view.oux, view.ouy, view.ouz};
  const std::size_t cols = static_cast<std::size_t>(view.cols);
  const int width = block_end - block_begin;
  for (int axis = 0; axis < 3; ++axis) {
    float* const lo = columns + axis * kColumnsPitch;
    float* const hi = columns + (3 + axis) * kColumnsPitch;
    const float* u = out[axis] + row0 * cols + block_begin;
    int i = row0;
    for (; row1 + 1 - i >= kRows; i += kRows, u += kRows * cols)
      rows_into_columns<V, kRows>(u, cols, width, lo, hi, fresh && i == row0);
    for (; row1 + 1 - i >= 2; i += 2, u += 2 * cols)
      rows_into_columns<V, 2>(u, cols, width, lo, hi, fresh && i == row0);
    for (; i <= row1; ++i, u += cols) rows_into_columns<V, 1>(u, cols, width, lo, hi, fresh && i == row0);
  }
}

// A bound widened by a value by the shared rules: the least (Lower) or the greatest.
template <bool Lower>
POND_KERNEL_INLINE float widest(float v, float acc) {
  return Lower ? shared::bound_below(acc, v) : shared::bound_above(acc, v);
}

// v widened by a whole tile's columns at `at` from its vector First on and, with Next, the column
// after them: the tile's vectors, then one more that overlaps them and ends at that 17th column
// (min and max may see a value twice); the least (Lower) or the greatest.
template <class V, bool Lower, bool Next, int First = 0>
POND_KERNEL_INLINE typename V::F widened_by_tile(const float* at, typename V::F v) {
  const auto widened = [&](const float* from) {
    return Lower ? V::min_of(V::load(from), v) : V::max_of(V::load(from), v);
  };
  for (int k = First; k < kTileCells / V::width; ++k) v = widened(at + k * V::width);
  if constexpr (Next) v = widened(at + kTileCells + 1 - V::width);
  return v;
}
// A whole tile's columns at `at` (and, with Next, the column after them) as one vector.
template <class V, bool Lower, bool Next>
POND_KERNEL_INLINE typename V::F of_tile(const float* at) {
  return widened_by_tile<V, Lower, Next, 1>(at, V::load(at));
}
template <class V, bool Lower>
POND_KERNEL_INLINE float reduced(typename V::F v) {
  return Lower ? V::reduce_min(v) : V::reduce_max(v);
}

// `b` widened by the values at `at`: `width` columns, and the column after them when `next`;
// the least (Lower) or the greatest.
template <class V, bool Lower>
POND_KERNEL_INLINE float tile_bound(float b, const float* at, int width, bool next) {
  if (width == kTileCells) {
    b = widest<Lower>(reduced<V, Lower>(of_tile<V, Lower, false>(at)), b);
  } else {
    for (int c = 0; c < width; ++c) b = widest<Lower>(at[c], b);
  }
  return next ? widest<Lower>(at[width], b) : b;
}

// Bounds k0 .. k0 + 2 (least or greatest x, y, z) of a whole tile with a column after it in the
// block (column c of the columns' bounds, when `have_columns`, and of `border`, when not null): one
// reduction a bound.
template <class V, bool Lower>
POND_KERNEL_INLINE void whole_tile_bounds(const float* columns, bool have_columns, const float* const* border, int c,
                                          float* bounds) {
  const int k0 = Lower ? 0 : 3;
  for (int k = k0; k < k0 + 3; ++k) {
    const float* first = have_columns ? columns + k * kColumnsPitch + c : border[k % 3] + c;
    typename V::F v = of_tile<V, Lower, true>(first);
    if (have_columns && border) v = widened_by_tile<V, Lower, true>(border[k % 3] + c, v);
    bounds[k] = widest<Lower>(reduced<V, Lower>(v), Lower ? kInf : -kInf);
  }
}

// Tile row `row` from a block's columns' bounds (when `have_columns`) and the new displacements of
// the row after them (`border`: x, y, z at the block's first column, when not null): each tile
// starting in the block from its columns there, and the tile ending at the block's first column
// widened by it (its other columns came with the block before).
template <class V>
POND_KERNEL_INLINE void flush_tiles(const TileGrid& grid, int block_begin, int block_end, const float* columns,
                                    bool have_columns, const float* const* border, TileBounds* row) {
  // Bound k (least x, y, z, greatest x, y, z) widened from b by columns [c, c + width), and c + width
  // when `next`.
  auto bound = [&](int k, float b, int c, int width, bool next) {
    const auto by = [&](const float* at) {
      return k < 3 ? tile_bound<V, true>(b, at, width, next) : tile_bound<V, false>(b, at, width, next);
    };
    if (have_columns) b = by(columns + k * kColumnsPitch + c);
    if (border) b = by(border[k % 3] + c);
    return b;
  };
  for (int a = block_begin / kTileCells; a < grid.tiles_x && a * kTileCells < block_end; ++a) {
    const int j = a * kTileCells, width = block_end - j < kTileCells ? block_end - j : kTileCells;
    const bool next = j + kTileCells < block_end;
    const int c = j - block_begin;
    if (width == kTileCells && next) {
      float b[6];
      whole_tile_bounds<V, true>(columns, have_columns, border, c, b);
      whole_tile_bounds<V, false>(columns, have_columns, border, c, b);
      row[a] = {b[0], b[1], b[2], b[3], b[4], b[5]};
      continue;
    }
    row[a] = {bound(0, kInf, c, width, next),   bound(1, kInf, c, width, next),   bound(2, kInf, c, width, next),
              bound(3, -kInf, c, width, next), bound(4, -kInf, c, width, next), bound(5, -kInf, c, width, next)};
  }
  if (block_begin > 0) {
    TileBounds& t = row[block_begin / kTileCells - 1];
    float* const bounds[6] = {&t.min_x, &t.min_y, &t.min_z, &t.max_x, &t.max_y, &t.max_z};
    for (int k = 0; k < 6; ++k) *bounds[k] = bound(k, *bounds[k], 0, 1, false);
  }
}

// What follows the integration of row i of rows [r0, r1) (tile_row_events): the end of the tile
// row before it (row i is its border), the last row of a pass (pass_rows()), the end of the range.
struct TileRowEvents {
  bool ends_tile_row, ends_pass, ends_range;
  bool any() const { return ends_tile_row || ends_pass || ends_range; }
};
// The rows a pass reads: a tile row's at its last row where a block is narrow enough for them
// still to be in the core's caches there; on wider blocks, the last four rows every four rows, as
// long tile rows leave the caches before they end.
inline constexpr int kNarrowBlock = 512;
POND_KERNEL_INLINE int pass_rows(int block_width) { return block_width > kNarrowBlock ? kWidePassRows : kTileCells; }
static_assert((kTileCells & (kTileCells - 1)) == 0 && (kWidePassRows & (kWidePassRows - 1)) == 0 &&
                  kTileCells % kWidePassRows == 0,
              "pass_rows() are powers of two that end every tile row");
POND_KERNEL_INLINE TileRowEvents tile_row_events(int i, int r1, int pass_rows) {
  return {i % kTileCells == 0 && i > 0, (i & (pass_rows - 1)) == pass_rows - 1, i == r1 - 1};
}

// After the integration of row i (of rows [r0, r1)) in columns [block_begin, block_end): a tile
// row row i ends goes to the sink, from the columns' bounds over its rows in [r0, i) and row i;
// at a pass's last row, or the range's, the columns' bounds take in the pass's rows (from the tile
// row's first in [r0, i] on), and at the range's end, that last tile row goes too, partial. Out of
// line (called where any of `events`): inlined, it changed the register allocation of the step's
// spring loop.
template <class W>
[[gnu::noinline]] void emit_tile_rows(const StepView& view, const TileGrid& grid, TileRowEvents events, int i,
                                      int r0, int block_begin, int block_end, TileSink& sink) {
  using V = typename BoundsWide<W>::type;
  auto flush = [&](int b, bool have_columns, const float* const* border) {
    flush_tiles<V>(grid, block_begin, block_end, sink.columns, have_columns, border,
                   sink.rows + static_cast<std::size_t>(b - sink.first_row) * grid.tiles_x);
  };
  if (events.ends_tile_row) {
    const std::size_t at = static_cast<std::size_t>(i) * static_cast<std::size_t>(view.cols) + block_begin;
    const float* const border[3] = {view.oux + at, view.ouy + at, view.ouz + at};
    flush(i / kTileCells - 1, i > r0, border);
  }
  if (events.ends_pass || events.ends_range) {
    const int first = i / kTileCells * kTileCells, start = first > r0 ? first : r0;
    const int rows = pass_rows(block_end - block_begin), row0 = i + 1 - rows > start ? i + 1 - rows : start;
    if (rows == kTileCells)
      narrow_block_bounds<V>(view, start, i, block_begin, block_end, sink.columns);
    else
      wide_block_bounds<V>(view, row0, i, block_begin, block_end, sink.columns, row0 == start);
    if (events.ends_range && i / kTileCells < grid.tiles_y) flush(i / kTileCells, true, nullptr);
  }
}

}  // namespace POND_ISA
}  // namespace pond::sim
