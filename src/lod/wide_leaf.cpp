// A candidate leaf wider than a block (at most two across) that the tile ranges do not prove,
// judged on the nodes of the blocks it covers: by its parts that each lie in one block (its
// children, or a child's children where the child is still wider). A part the ranges prove against
// t's interpolation needs no node; the others are scanned against it, after quick rejects at the
// splits. Every part passes an exact test in the end, so the verdict is the one a single block
// holding all of t would give.
#include <algorithm>

#include "lod/lod_builder.h"
#include "lod/position_copy.h"
#include "lod/range_proof.h"
#include "lod/triangle_scan.h"

namespace pond::lod {
namespace {

Point block_of(const Tri& t) {
  const CellBox b = box_of(t);
  return {block_at(b.x0), block_at(b.y0)};
}

}  // namespace

LodBuilder::Fit LodBuilder::wide_leaf_fits(const Tri& t, Point m) {
  // The parts, and for each the split between it and t: m, or a half's midpoint c too.
  Tri tris[4];
  Point split[4], leg[4][2];  // for a quarter: its half's midpoint c and the leg of t that c halves
  bool deeper[4];
  int n = 0;
  for (const Tri& half : {child_left(t, m), child_right(t, m)}) {
    Point c;
    if (in_one_block(box_of(half)) || !midpoint(half, c)) {
      tris[n] = half, deeper[n++] = false;
    } else {
      for (const Tri& quarter : {child_left(half, c), child_right(half, c)}) {
        tris[n] = quarter, split[n] = c, deeper[n] = true;
        leg[n][0] = half.left, leg[n++][1] = half.right;
      }
    }
  }
  // Parts the tile ranges prove against t's interpolation need no nodes (t as a whole failed them).
  // If one is left, every part's block must be on the host (t's corners and splits are in them),
  // all asked for at once; only the others' blocks are made.
  const Point vertices[3] = {t.apex, t.left, t.right};
  const RangeProof range_proof(*ranges_, *box_budget_);
  const RangeProof::Span3 range = range_proof.interpolation_range(vertices);  // every part's
  bool ranged[4], all_ranged = true, held = true;
  for (int k = 0; k < n; ++k) {
    const CellBox b = box_of(tris[k]);
    ranged[k] = range_proof.proves(b.x0, b.x1, b.y0, b.y1, range);
    all_ranged = all_ranged && ranged[k];
  }
  if (all_ranged) {
    ++stats_.ranged;
    note_corners(vertices);
    return Fit::yes;
  }
  for (int k = 0; k < n; ++k) {
    const Point b = block_of(tris[k]);
    held = block_held(b.x, b.y) && held;
  }
  if (!held) {
    --stats_.tested;  // tested again once its blocks are brought
    return Fit::later;
  }
  const auto at = [&](Point p) { return world_position(positions_, p.y, p.x); };
  // A split vertex v (the midpoint of m's hypotenuse or of one of t's legs) against t's
  // interpolation there, the average of that edge's ends: squared, in double.
  const auto squared_deviation = [&](Point v, Point e0, Point e1) {
    const auto pv = at(v), a = at(e0), b = at(e1);
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = pv[k] - 0.5 * (double(a[k]) + b[k]);
      d2 += d * d;
    }
    return d2;
  };
  // Part k's node v over its own budget fails t at once (the exact test would find it).
  const auto over = [&](double d2, Point v, int k) {
    const Point b = block_of(tris[k]);
    const SurfaceBlock& blk = blocks_.block(b.x, b.y);
    const double budget = blk.budget[blk.grid->id({v.x - blk.origin.x, v.y - blk.origin.y})];
    return d2 > budget * budget;
  };
  const int first = static_cast<int>(std::find(ranged, ranged + n, false) - ranged);
  if (over(squared_deviation(m, t.left, t.right), m, first)) return Fit::no;  // every part has m as a corner
  for (int k = 0; k < n; ++k)
    if (deeper[k] && !ranged[k] && over(squared_deviation(split[k], leg[k][0], leg[k][1]), split[k], k)) return Fit::no;
  TriCorners corners;
  const Point corner[3] = {t.apex, t.left, t.right};
  for (int k = 0; k < 3; ++k) {
    const auto p = at(corner[k]);
    corners.x[k] = p[0], corners.y[k] = p[1], corners.z[k] = p[2];
  }
  ++stats_.scanned;
  for (int k = 0; k < n; ++k) {
    if (ranged[k]) continue;
    const Point b = block_of(tris[k]);
    const SurfaceBlock& blk = blocks_.block(b.x, b.y);
    if (!within_budget(*blk.grid, blk.positions(), blk.scan_budgets(), largest_, blk.local(t), corners,
                       blk.local(tris[k]), &stats_.scanned_nodes))
      return Fit::no;
  }
  return Fit::yes;
}

}  // namespace pond::lod
