#pragma once
// The builder's coarse test: a region's nodes all within budget of an interpolation between some of
// its nodes, proved from the tile ranges (tile_ranges.h) alone: no node is read, so the test needs
// none of the positions on the host. A node's deviation from the rest grid lies in its tile's
// [lo, hi] and the interpolation's between the corners' least and greatest (each corner's from the
// ranges of the tiles holding it), so the two differ by at most the larger of hi - least and
// greatest - lo. Each cell of the range pyramid is held against the least budget of its own world
// box (camera_budget.h); a cell that fails is tried by its four quarters, down to single tiles, so
// a long triangle is not judged by its nearest node's budget and its farthest wave at once.
#include <span>

#include "lod/camera_budget.h"
#include "lod/grid_hierarchy.h"
#include "lod/tile_ranges.h"

namespace pond::lod {

class RangeProof {
 public:
  RangeProof(const TileRanges& ranges, const BoxBudget& budget) : ranges_(ranges), budget_(budget) {}

  // The range of the piecewise-linear interpolation between `corners` (grid nodes), per
  // coordinate, from the tile ranges of the tiles holding them.
  struct Span3 {
    double least[3], greatest[3];
  };
  Span3 interpolation_range(std::span<const Point> corners) const;

  // Are the nodes of columns [x0, x1] and rows [y0, y1] (inside the grid) within budget of the
  // interpolation between `corners`, whose range is `range`? (Parts of one triangle share it.)
  bool proves(int x0, int x1, int y0, int y1, const Span3& range) const;
  bool proves(int x0, int x1, int y0, int y1, std::span<const Point> corners) const {
    return proves(x0, x1, y0, y1, interpolation_range(corners));
  }

 private:
  struct Band {
    const Span3& range;
    int x0, x1, y0, y1;  // the region's nodes
  };
  bool cell_proves(int k, int a, int b, const Band& band, int& checks) const;

  const TileRanges& ranges_;
  const BoxBudget& budget_;
};

}  // namespace pond::lod
