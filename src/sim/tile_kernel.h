#pragma once
// The tile bounds (shared/tile_bounds.h) as a by-product of the step kernel (step_kernel.h): every
// few rows the kernel has integrated in a block of columns, their new displacements, still in the
// core's caches, are read back a tile's width of columns at a time into each column's bounds over
// the tile row so far (TileSink::columns); at the end of a tile row, its tiles come from those.
// Min and max are exact: the tiles' values do not depend on the width or the order of the
// operations, only the sign of a zero bound may, and the solver's merge makes every zero +0.
#include <cstddef>

#include "sim/chunks.h"
#include "sim/isa_namespace.h"
#include "sim/step_view.h"
#include "sim/tile_bounds.h"
#include "sim/wide_scalar.h"
#include "sim/wide_sse2.h"

namespace pond::sim {
inline namespace POND_ISA {

// Rows integrated between two reads of their new displacements: few enough that those are still
// in the core's caches, enough that the columns' bounds are read and written seldom.
inline constexpr int kTilePassRows = 4;  // divides POND_TILE_CELLS
inline constexpr int kTileCells = POND_TILE_CELLS;

// The wide table the bounds use with backend W: W's own, and SSE2's (the baseline of x86-64 and
// of the IA-32 build) for the scalar backend, whose one-lane table would keep 32 bounds per tile.
template <class W>
struct BoundsWide {
  using type = W;
};
template <>
struct BoundsWide<WideScalar> {
  using type = WideSse2;
};

// The columns [j, j + K * V::width) (a tile's width; `column` is column j's bounds in
// TileSink::columns) widened by the new displacements of rows [row0, row1], or restarted from
// them: row by row, in registers.
template <class V, int K>
POND_KERNEL_INLINE void group_bounds(const StepView& view, int row0, int row1, int j, float* column, bool restart) {
  const float* const out[3] = {view.oux, view.ouy, view.ouz};
  const std::size_t cols = static_cast<std::size_t>(view.cols);
  for (int axis = 0; axis < 3; ++axis) {
    float* const lo_at = column + axis * kColumnsPitch;
    float* const hi_at = column + (3 + axis) * kColumnsPitch;
    typename V::F lo[K], hi[K];
    for (int k = 0; k < K; ++k) {
      lo[k] = restart ? V::set1(kInf) : V::load(lo_at + k * V::width);
      hi[k] = restart ? V::set1(-kInf) : V::load(hi_at + k * V::width);
    }
    const float* u = out[axis] + row0 * cols + j;
    for (int i = row0; i <= row1; ++i, u += cols)
      for (int k = 0; k < K; ++k) {
        const typename V::F x = V::load(u + k * V::width);
        lo[k] = V::min_of(x, lo[k]);
        hi[k] = V::max_of(x, hi[k]);
      }
    for (int k = 0; k < K; ++k) {
      V::store(lo_at + k * V::width, lo[k]);
      V::store(hi_at + k * V::width, hi[k]);
    }
  }
}

// The columns' bounds of a block widened by rows [row0, row1] (all integrated), or restarted.
template <class V>
POND_KERNEL_INLINE void block_bounds(const StepView& view, int row0, int row1, int block_begin, int block_end,
                                     float* columns, bool restart) {
  int j = block_begin;
  for (; block_end - j >= kTileCells; j += kTileCells)
    group_bounds<V, kTileCells / V::width>(view, row0, row1, j, columns + (j - block_begin), restart);
  for (; j < block_end; ++j) group_bounds<WideScalar, 1>(view, row0, row1, j, columns + (j - block_begin), restart);
}

// One bound of a tile from its columns' bounds at `at` (`width` columns, and the column after
// them when `next`): the least (Lower) or the greatest.
template <class V, bool Lower>
POND_KERNEL_INLINE float tile_bound(const float* at, int width, bool next) {
  auto pick = [](float v, float acc) { return Lower ? (v < acc ? v : acc) : (v > acc ? v : acc); };
  float b = Lower ? kInf : -kInf;
  if (width == kTileCells) {
    typename V::F v = V::load(at);
    for (int k = 1; k < kTileCells / V::width; ++k)
      v = Lower ? V::min_of(V::load(at + k * V::width), v) : V::max_of(V::load(at + k * V::width), v);
    b = Lower ? V::reduce_min(v) : V::reduce_max(v);
  } else {
    for (int c = 0; c < width; ++c) b = pick(at[c], b);
  }
  return next ? pick(at[width], b) : b;
}

// Tile row `row` from the columns' bounds of a block: each tile starting in the block from its
// columns there, and the tile ending at the block's first column widened by it (its other columns
// came with the block before).
template <class V>
POND_KERNEL_INLINE void flush_tiles(const TileGrid& grid, int block_begin, int block_end, const float* columns,
                                    TileBounds* row) {
  for (int a = block_begin / kTileCells; a < grid.tiles_x && a * kTileCells < block_end; ++a) {
    const int j = a * kTileCells, width = block_end - j < kTileCells ? block_end - j : kTileCells;
    const bool next = j + kTileCells < block_end;
    const float* at = columns + (j - block_begin);
    row[a] = {tile_bound<V, true>(at, width, next),
              tile_bound<V, true>(at + kColumnsPitch, width, next),
              tile_bound<V, true>(at + 2 * kColumnsPitch, width, next),
              tile_bound<V, false>(at + 3 * kColumnsPitch, width, next),
              tile_bound<V, false>(at + 4 * kColumnsPitch, width, next),
              tile_bound<V, false>(at + 5 * kColumnsPitch, width, next)};
  }
  if (block_begin > 0) {
    TileBounds& t = row[block_begin / kTileCells - 1];
    float* const bounds[6] = {&t.min_x, &t.min_y, &t.min_z, &t.max_x, &t.max_y, &t.max_z};
    for (int k = 0; k < 6; ++k) {
      const float v = columns[k * kColumnsPitch];
      *bounds[k] = k < 3 ? (v < *bounds[k] ? v : *bounds[k]) : (v > *bounds[k] ? v : *bounds[k]);
    }
  }
}

// After the integration of row i (of rows [r0, r1)) in columns [block_begin, block_end): every
// kTilePassRows rows, and at the end of a tile row or of the range, the rows since the last such
// pass join the columns' bounds (the range's first pass restarts them); a tile row row i ends goes
// to the sink, and the columns' bounds restart from row i, the first of the next tile row; at the
// range's end, its last tile row goes too, partial.
template <class W>
POND_KERNEL_INLINE void emit_tile_rows(const StepView& view, const TileGrid& grid, int i, int r0, int r1,
                                       int block_begin, int block_end, TileSink& sink) {
  using V = typename BoundsWide<W>::type;
  const bool ends_tile_row = i % kTileCells == 0 && i > 0, ends_range = i == r1 - 1;
  if (!ends_tile_row && !ends_range && i % kTilePassRows != kTilePassRows - 1) return;
  // The last pass before row i: after a row i - 1 - i % kTilePassRows, or at a tile row's start.
  const int after_rows = i - 1 - i % kTilePassRows;
  const int at_tile_row = i - 1 >= kTileCells ? (i - 1) / kTileCells * kTileCells : -1;
  int last = after_rows > at_tile_row ? after_rows : at_tile_row;
  last = last > r0 - 1 ? last : r0 - 1;
  block_bounds<V>(view, last + 1, i, block_begin, block_end, sink.columns, last < r0);
  auto flush = [&](int b) {
    flush_tiles<V>(grid, block_begin, block_end, sink.columns,
                   sink.rows + static_cast<std::size_t>(b - sink.first_row) * grid.tiles_x);
  };
  if (ends_tile_row) {
    flush(i / kTileCells - 1);
    block_bounds<V>(view, i, i, block_begin, block_end, sink.columns, true);
  }
  if (ends_range && i / kTileCells < grid.tiles_y) flush(i / kTileCells);
}

}  // namespace POND_ISA
}  // namespace pond::sim
