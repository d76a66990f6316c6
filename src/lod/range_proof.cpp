#include "lod/range_proof.h"

#include <algorithm>
#include <array>
#include <cmath>


namespace pond::lod {
namespace {

// Cells tried per test at most: past this the triangle is split instead (a bounded cost).
constexpr int kMostChecks = 48;

}  // namespace

RangeProof::Span3 RangeProof::interpolation_range(std::span<const Point> corners) const {
  const TileBounds c = ranges_.hull_at(corners);
  return {{c.min_x, c.min_y, c.min_z}, {c.max_x, c.max_y, c.max_z}};
}

bool RangeProof::proves(int x0, int x1, int y0, int y1, const Span3& range) const {
  const Band band{range, x0, x1, y0, y1};
  const TileRect tiles = ranges_.tiles_of(x0, x1, y0, y1);
  const int k = ranges_.level_for(tiles);
  int checks = 0;
  for (int b = tiles.b0 >> k; b <= tiles.b1 >> k; ++b)
    for (int a = tiles.a0 >> k; a <= tiles.a1 >> k; ++a)
      if (!cell_proves(k, a, b, band, checks)) return false;
  return true;
}

bool RangeProof::cell_proves(int k, int a, int b, const Band& band, int& checks) const {
  if (a >= ranges_.cells_x(k) || b >= ranges_.cells_y(k)) return true;  // past the grid: no tiles
  // The cell's nodes within the region.
  const int span = kTileCells << k;
  const int x0 = std::max(band.x0, a * span), x1 = std::min(band.x1, (a + 1) * span);
  const int y0 = std::max(band.y0, b * span), y1 = std::min(band.y1, (b + 1) * span);
  if (x0 > x1 || y0 > y1) return true;
  if (++checks > kMostChecks) return false;
  const TileBounds& r = ranges_.cell(k, a, b);
  const double wx = std::max(r.max_x - band.range.least[0], band.range.greatest[0] - r.min_x);
  const double wy = std::max(r.max_y - band.range.least[1], band.range.greatest[1] - r.min_y);
  const double wz = std::max(r.max_z - band.range.least[2], band.range.greatest[2] - r.min_z);
  const double error = std::sqrt(wx * wx + wy * wy + wz * wz) * (1 + 1e-12);
  if (const TileRanges::WorldBox box = ranges_.world_box(x0, x1, y0, y1, r); budget_.allows(error, box.lo, box.hi))
    return true;
  if (k == 0) return false;
  for (int q = 0; q < 4; ++q)
    if (!cell_proves(k - 1, 2 * a + (q & 1), 2 * b + (q >> 1), band, checks)) return false;
  return true;
}

}  // namespace pond::lod
