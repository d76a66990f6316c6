#pragma once
// What the LOD builder knows of the surface before it reads a node: per tile of the solvers' tile
// grid (shared/tile_bounds.h: 16 x 16 cells, neighbours share their border nodes), the range of each
// world coordinate's deviation from the rest grid, node (row, col) resting at (col h, 0, row h).
// An interpolation over nodes of a region misses any node of it by at most the length of the
// region's ranges' widths (the rest grid is linear, so it interpolates exactly), and the region's
// world box is its rest box widened by the ranges: that is all the builder's coarse test needs.
// A pyramid of 2^k x 2^k tile blocks covers a rectangle of tiles in a few cells (range_proof.h).
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <span>
#include <vector>

#include "lod/grid_hierarchy.h"
#include "lod/node_positions.h"
#include "shared/tile_bounds.h"

namespace pond::lod {

using shared::TileBounds;

constexpr int kTileCells = POND_TILE_CELLS;

// A rectangle of tiles, inclusive.
struct TileRect {
  int a0, a1;  // tile columns
  int b0, b1;  // tile rows
};

class TileRanges {
 public:
  TileRanges() = default;
  // `tiles`: tiles_along(cols) x tiles_along(rows) ranges in world units, element b * tiles_x + a,
  // each min <= max (a tile with no finite node has none); `largest` bounds every |world coordinate|.
  TileRanges(int rows, int cols, double spacing, std::vector<TileBounds> tiles, float largest);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  int tiles_x() const { return tiles_x_; }
  int tiles_y() const { return tiles_y_; }
  double spacing() const { return spacing_; }
  float largest() const { return largest_; }

  // The tiles holding every node of columns [x0, x1] and rows [y0, y1] (inside the grid).
  TileRect tiles_of(int x0, int x1, int y0, int y1) const {
    // Node k lies in tiles (k - 1) / kTileCells and k / kTileCells (unsigned: k >= 0, a shift).
    const auto first = [](int k, int tiles) { return std::min(static_cast<int>(static_cast<unsigned>(k) / kTileCells), tiles - 1); };
    const auto last = [](int k, int tiles) {
      return k > 0 ? std::min(static_cast<int>(static_cast<unsigned>(k - 1) / kTileCells), tiles - 1) : 0;
    };
    const int a0 = first(x0, tiles_x_), b0 = first(y0, tiles_y_);
    return {a0, std::max(a0, last(x1, tiles_x_)), b0, std::max(b0, last(y1, tiles_y_))};
  }
  // The pyramid: level k's cells are blocks of 2^k x 2^k tiles, cells_x(k) x cells_y(k) of them.
  int levels() const { return static_cast<int>(levels_.size()); }
  int cells_x(int k) const { return dims_[static_cast<std::size_t>(k)].first; }
  int cells_y(int k) const { return dims_[static_cast<std::size_t>(k)].second; }
  const TileBounds& cell(int k, int a, int b) const {
    return levels_[static_cast<std::size_t>(k)][static_cast<std::size_t>(b) * static_cast<std::size_t>(cells_x(k)) +
                                                static_cast<std::size_t>(a)];
  }
  // A range of node (col x, row y)'s deviation: the intersection of the tiles holding it (up to
  // four: neighbours share their border nodes), so reading no node.
  TileBounds at_node(int x, int y) const;
  // The world box of the nodes of columns [x0, x1] and rows [y0, y1] whose deviations lie in `r`
  // (a tile's or a pyramid cell's range): their rest box widened by it.
  struct WorldBox {
    std::array<double, 3> lo, hi;
  };
  WorldBox world_box(int x0, int x1, int y0, int y1, const TileBounds& r) const {
    const double h = spacing_;
    return {{x0 * h + r.min_x, double(r.min_y), y0 * h + r.min_z}, {x1 * h + r.max_x, double(r.max_y), y1 * h + r.max_z}};
  }
  // The hull of at_node over `nodes`: each coordinate's least lower and greatest upper bound.
  TileBounds hull_at(std::span<const Point> nodes) const;
  // The level whose cells cover `r` in at most a few (2 x 2, or 2 x 3 for a 1 x 2 rectangle): cells
  // of the largest power of two tiles within r's shorter side.
  int level_for(const TileRect& r) const {
    const int side = std::min(r.a1 - r.a0, r.b1 - r.b0) + 1;
    return std::min(static_cast<int>(std::bit_width(static_cast<unsigned>(side))), static_cast<int>(dims_.size())) - 1;
  }

 private:
  int rows_ = 0, cols_ = 0, tiles_x_ = 0, tiles_y_ = 0;
  double spacing_ = 1;
  float largest_ = 0;
  // levels_[k]: the ranges of 2^k x 2^k tile blocks, (dims_[k].first wide) row by row.
  std::vector<std::vector<TileBounds>> levels_;
  std::vector<std::pair<int, int>> dims_;
};

// From node positions, node by node (a file's state: O(nodes)). The rest grid's spacing is the mean
// spacing along the first row; any spacing gives true ranges, a wrong one only wider ones.
// Throws InputError naming the first node with a non-finite coordinate.
TileRanges tile_ranges(const NodePositions& positions);

// From the solvers' tile bounds (shared/tile_bounds.h: displacements in grid units) of a grid of
// this spacing, in O(tiles): widened by the float rounding of the world conversion
// (node_positions.h). Throws InputError when a bound is not finite.
TileRanges tile_ranges(std::span<const TileBounds> displacement_bounds, int rows, int cols, float spacing);

}  // namespace pond::lod
