#include "sim/tile_bounds.h"

#include <algorithm>


namespace pond::sim {
namespace {

constexpr int kCells = POND_TILE_CELLS;

TileBounds node_bounds(const WaterState& s, std::size_t n) { return {s.ux[n], s.uy[n], s.uz[n], s.ux[n], s.uy[n], s.uz[n]}; }

void make_canonical(TileBounds& t) { t = shared::bounds_canonical(t); }

// The tiles holding node index k of a side of `tiles` tiles: k / 16, and the one before where k
// is a shared border.
int first_tile(int k) { return k > 0 ? (k - 1) / kCells : 0; }
int last_tile(int k, int tiles) { return std::min(k / kCells, tiles - 1); }

}  // namespace

TileGrid::TileGrid(int node_rows, int node_cols)
    : rows(node_rows), cols(node_cols), tiles_x(static_cast<int>(shared::tiles_along(static_cast<shared::uint>(node_cols)))),
      tiles_y(static_cast<int>(shared::tiles_along(static_cast<shared::uint>(node_rows)))) {}

TileRowSpan tile_rows_of(int r0, int r1, int rows) {
  const int tiles_y = static_cast<int>(shared::tiles_along(static_cast<shared::uint>(rows)));
  return {first_tile(r0), last_tile(r1 - 1, tiles_y)};
}

std::vector<TileBounds> compute_tile_bounds(const WaterState& state, const TileGrid& grid) {
  std::vector<TileBounds> bounds(grid.tiles());
  recompute_tiles(bounds, state, grid, {0, grid.rows - 1, 0, grid.cols - 1});
  return bounds;
}

void recompute_tiles(std::vector<TileBounds>& bounds, const WaterState& state, const TileGrid& grid,
                     const NodeRect& moved) {
  for (int b = first_tile(moved.row0); b <= last_tile(moved.row1, grid.tiles_y); ++b)
    for (int a = first_tile(moved.col0); a <= last_tile(moved.col1, grid.tiles_x); ++a) {
      TileBounds t = kNoNodes;
      for (int i = b * kCells; i <= std::min(b * kCells + kCells, grid.rows - 1); ++i)
        for (int j = a * kCells; j <= std::min(a * kCells + kCells, grid.cols - 1); ++j)
          widen(t, node_bounds(state, static_cast<std::size_t>(i) * grid.cols + j));
      make_canonical(t);
      bounds[static_cast<std::size_t>(b) * grid.tiles_x + a] = t;
    }
}

void merge_tile_rows(std::vector<TileBounds>& bounds, const TileGrid& grid, const std::vector<TileRowSpan>& spans,
                     const std::vector<const TileBounds*>& parts) {
  int done = 0;  // tile rows below this one were written by an earlier part
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (int b = spans[p].first; b <= spans[p].last; ++b) {
      const TileBounds* from = parts[p] + static_cast<std::size_t>(b - spans[p].first) * grid.tiles_x;
      TileBounds* to = bounds.data() + static_cast<std::size_t>(b) * grid.tiles_x;
      for (int a = 0; a < grid.tiles_x; ++a) {
        if (b >= done) to[a] = kNoNodes;
        widen(to[a], from[a]);
      }
      done = std::max(done, b + 1);
    }
  for (TileBounds& t : bounds) make_canonical(t);
}

}  // namespace pond::sim
