#pragma once
// Per-frame nested error bounds, one pass over the nodes from the finest scale up (O(nodes)),
// recomputed every frame because the surface moves. For a split vertex v (the hypotenuse
// midpoint of the triangles T of its diamond):
//   deviation(v) = |P(v) - (P(end0) + P(end1)) / 2|   (v against T's interpolation: weights 0, 1/2, 1/2)
//   bound(v)     = deviation(v) + max over v's children c of bound(c)
//   min_budget(v) = min(budget(v), min over children of min_budget(c))
// bound(v) bounds the distance of every node of T from T's interpolation: a node p in child T1
// misses T by at most |p - I_T1(p)| + |I_T1(p) - I_T(p)|, and I_T1 - I_T is linear on T1, zero at
// its other two vertices and deviation(v) at v. min_budget(v) covers every node of T (and a bit
// more: the children's diamonds reach outside T, which only makes it smaller). So
// bound(v) <= min_budget(v) proves T needs no split: a quick, conservative accept.
#include <limits>

#include "lod/grid_hierarchy.h"
#include "lod/node_positions.h"

namespace pond::lod {

// positions: stride 1 (the builder's own copy). One NestedBound per node, written for the same
// vertices every frame. The others must hold kNothingProved, set once by the caller: tile corners
// (always split, never tested) and vertices whose hypotenuse leaves the grid (their triangles are
// clipped and always scanned), so that their parents prove nothing from them either.
// Both numbers of a split vertex side by side: the refinement reads them together.
struct NestedBound {
  float error;       // bound(v)
  float min_budget;  // min_budget(v)
};

constexpr NestedBound kNothingProved{std::numeric_limits<float>::infinity(), 0.0f};

// `largest` bounds every |coordinate| (it sizes the float rounding slack).
void nested_bounds(const GridHierarchy& grid, const NodePositions& positions, float largest,
                   const float* budget, NestedBound* bounds);

}  // namespace pond::lod
