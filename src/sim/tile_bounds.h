#pragma once
// The tile bounds on the CPU (layout and rules: shared/tile_bounds.h): their grid, their reference
// computation from a state, the recomputation of the tiles under nodes moved after a step, and the
// merge of the partial tile rows of the threads' row ranges.
#include <cstddef>
#include <limits>
#include <vector>

#include "shared/tile_bounds.h"
#include "sim/state.h"

namespace pond::sim {

using shared::TileBounds;

// No node yet: every bound widens from here.
inline constexpr float kInf = std::numeric_limits<float>::infinity();
inline constexpr TileBounds kNoNodes{kInf, kInf, kInf, -kInf, -kInf, -kInf};

// t widened by the bounds `by` (or by one node: {x, y, z, x, y, z}), by the shared rules.
inline void widen(TileBounds& t, const TileBounds& by) { t = shared::bounds_widened(t, by); }

// A rectangle of nodes, inclusive.
struct NodeRect {
  int row0, row1, col0, col1;
};

struct TileGrid {
  int rows = 0, cols = 0;        // nodes
  int tiles_x = 0, tiles_y = 0;  // tiles along a row, along a column
  TileGrid() = default;
  TileGrid(int node_rows, int node_cols);
  std::size_t tiles() const { return static_cast<std::size_t>(tiles_x) * static_cast<std::size_t>(tiles_y); }
};

// The tile rows [first, last] holding any of the node rows [r0, r1) (r0 < r1).
struct TileRowSpan {
  int first, last;
  int count() const { return last - first + 1; }
};
TileRowSpan tile_rows_of(int r0, int r1, int rows);

// Every tile's bounds of `state`, node by node: the reference the kernels must equal.
std::vector<TileBounds> compute_tile_bounds(const WaterState& state, const TileGrid& grid);

// Recomputes, in `bounds`, the tiles holding any node of `moved` from `state`.
void recompute_tiles(std::vector<TileBounds>& bounds, const WaterState& state, const TileGrid& grid,
                     const NodeRect& moved);

// The bounds from the kernels' partial tile rows: part p's tile rows spans[p] at parts[p],
// merged in part order into `bounds`, then their zeros made +0.
void merge_tile_rows(std::vector<TileBounds>& bounds, const TileGrid& grid, const std::vector<TileRowSpan>& spans,
                     const std::vector<const TileBounds*>& parts);

}  // namespace pond::sim
