// The tile bounds the LOD builder descends (issue 30), declared once for GLSL and C++.
//
// Tiles: the water grid's cells in squares of POND_TILE_CELLS x POND_TILE_CELLS. Tile (a, b) holds
// the nodes of rows [16b, min(16b + 16, rows - 1)] and columns [16a, min(16a + 16, cols - 1)]:
// neighbouring tiles share their border row or column of nodes, and the last tile of a row or
// column of tiles may be narrower. Tile (a, b) is element b * tiles_x + a.
//
// Bounds: per tile, the least and the greatest of each displacement component (ux, uy, uz; the
// state's u, grid units) over the tile's nodes. Defined so that every backend and every split of
// the rows gives the same bits: NaN displacements are ignored (a tile of NaNs only has +inf as
// its minimum and -inf as its maximum), and a zero bound is +0 (-0 and +0 are the same value).
#ifndef POND_TILE_BOUNDS_H
#define POND_TILE_BOUNDS_H

#include "shared/exact_math.h"

#define POND_TILE_CELLS 16  // cells along a tile's side

#ifdef __cplusplus
#define POND_TILE_FN inline
namespace pond::shared {
#else
#define POND_TILE_FN
#endif

// 24 bytes, a float's alignment: the same layout in C++ and in a std430 array.
struct TileBounds {
  float min_x, min_y, min_z;
  float max_x, max_y, max_z;
};

// Tiles along a side of `nodes` nodes (at least one).
POND_TILE_FN uint tiles_along(uint nodes) { return nodes > 1u ? (nodes + uint(POND_TILE_CELLS - 2)) / uint(POND_TILE_CELLS) : 1u; }

// The two steps every bound is built from, in this operand order: v where v is below (above) acc,
// else acc; an accumulator that starts at +inf (-inf) so never holds NaN and NaN values are
// skipped. (This is x86's minps(v, acc) and maxps(v, acc).)
POND_TILE_FN float bound_below(float acc, float v) { return v < acc ? v : acc; }
POND_TILE_FN float bound_above(float acc, float v) { return v > acc ? v : acc; }
// A finished bound with -0 as +0, every other value unchanged (what IEEE's bound + 0 gives, on the
// bits: exact_math.h's plus_zero).
POND_TILE_FN float bound_canonical(float bound) { return plus_zero(bound); }

// t widened by the bounds `by` (or by one node: {x, y, z, x, y, z}), and t with its zeros made +0:
// the two steps every backend builds a tile from (C++ and GLSL alike pass structs by value here).
POND_TILE_FN TileBounds bounds_widened(TileBounds t, TileBounds by) {
  t.min_x = bound_below(t.min_x, by.min_x);
  t.min_y = bound_below(t.min_y, by.min_y);
  t.min_z = bound_below(t.min_z, by.min_z);
  t.max_x = bound_above(t.max_x, by.max_x);
  t.max_y = bound_above(t.max_y, by.max_y);
  t.max_z = bound_above(t.max_z, by.max_z);
  return t;
}
POND_TILE_FN TileBounds bounds_canonical(TileBounds t) {
  t.min_x = bound_canonical(t.min_x);
  t.min_y = bound_canonical(t.min_y);
  t.min_z = bound_canonical(t.min_z);
  t.max_x = bound_canonical(t.max_x);
  t.max_y = bound_canonical(t.max_y);
  t.max_z = bound_canonical(t.max_z);
  return t;
}

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#undef POND_TILE_FN

#endif  // POND_TILE_BOUNDS_H
