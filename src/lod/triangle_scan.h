#pragma once
// The exact test of one candidate leaf: does every node in the closed triangle lie within its
// budget of the triangle's interpolation (barycentric in index space)? Used for a block's
// triangles, a wide leaf's parts, and the parts of a whole-grid triangle its nested bounds cannot
// prove; stops at the first row with a node over budget.
#include <cstddef>

#include "lod/grid_hierarchy.h"
#include "lod/node_positions.h"

namespace pond::lod {

// Rows are read eight nodes at a time (four without AVX2; short rows in pieces of four): the
// position and budget arrays must stay readable this many floats past the last node (values there
// are ignored).
constexpr std::size_t kScanOverread = 7;

// The nodes' budgets and, from them (scan_thresholds()), the squared miss at or below which a
// node is surely within its budget however float rounds: most rows need that one compare a node.
struct ScanBudgets {
  const float* budget;
  const float* sure2;
  bool wide;  // the AVX2 copy of the scan may run (scan_rows.h): callers pass SurfaceBlock::wide
};

// Writes sure2 for the n nodes of `budget`, of positions whose |coordinates| are at most
// `largest`. Both arrays are readable and writable kScanOverread floats past the last node. With
// `wide` (ScanBudgets::wide), by an AVX2 copy: the same bits.
void scan_thresholds(const float* budget, std::size_t n, float largest, float* sure2, bool wide);

// positions: stride 1; `largest` bounds every |coordinate| (it sizes the float rounding margin).
// Counts the nodes visited into *visited (statistics).
bool within_budget(const GridHierarchy& grid, const NodePositions& positions, const ScanBudgets& budgets,
                   float largest, const Tri& t, long long* visited);

// The same test for the nodes of `region`, a triangle inside t (one of its descendants), against
// t's interpolation.
bool within_budget(const GridHierarchy& grid, const NodePositions& positions, const ScanBudgets& budgets,
                   float largest, const Tri& t, const Tri& region, long long* visited);

// The same test where t's corners need not be in `positions` (a triangle over several blocks,
// `region` inside the one `positions` holds, all in its coordinates): their world positions, apex,
// left, right.
struct TriCorners {
  float x[3], y[3], z[3];
};
bool within_budget(const GridHierarchy& grid, const NodePositions& positions, const ScanBudgets& budgets,
                   float largest, const Tri& t, const TriCorners& corners, const Tri& region, long long* visited);

// The same test for the fan (corner[0], corner[k], corner[k+1]) of a clipped triangle, in double.
bool fan_within_budget(const GridPolygon& polygon, const NodePositions& positions,
                       const float* budget, long long* visited);

}  // namespace pond::lod
