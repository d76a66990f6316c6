#include "lod/tile_ranges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.h"
#include "lod/position_copy.h"
#include "sim/wide_baseline.h"

namespace pond::lod {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr TileBounds kEmpty{kInf, kInf, kInf, -kInf, -kInf, -kInf};

// The float at or below (above) a double.
float down(double v) {
  const float f = static_cast<float>(v);
  return double(f) > v ? std::nextafter(f, -kInf) : f;
}
float up(double v) {
  const float f = static_cast<float>(v);
  return double(f) < v ? std::nextafter(f, kInf) : f;
}

int tiles_on(int nodes) { return static_cast<int>(shared::tiles_along(static_cast<shared::uint>(nodes))); }

}  // namespace

TileRanges::TileRanges(int rows, int cols, double spacing, std::vector<TileBounds> tiles, float largest)
    : rows_(rows), cols_(cols), tiles_x_(tiles_on(cols)), tiles_y_(tiles_on(rows)), spacing_(spacing),
      largest_(largest) {
  dims_.push_back({tiles_x_, tiles_y_});
  levels_.push_back(std::move(tiles));
  while (dims_.back().first > 1 || dims_.back().second > 1) {
    const auto [w, h] = dims_.back();
    const int nw = (w + 1) / 2, nh = (h + 1) / 2;
    const std::vector<TileBounds>& fine = levels_.back();
    std::vector<TileBounds> coarse(static_cast<std::size_t>(nw) * static_cast<std::size_t>(nh), kEmpty);
    for (int b = 0; b < h; ++b)
      for (int a = 0; a < w; ++a)
      {
        TileBounds& c = coarse[static_cast<std::size_t>(b / 2) * nw + a / 2];
        c = shared::bounds_widened(c, fine[static_cast<std::size_t>(b) * w + a]);
      }
    dims_.push_back({nw, nh});
    levels_.push_back(std::move(coarse));
  }
}

TileBounds TileRanges::at_node(int x, int y) const {
  const Point node{x, y};
  return hull_at(std::span(&node, 1));
}

TileBounds TileRanges::hull_at(std::span<const Point> nodes) const {
  // A node's tiles: one, two (on a tile border) or four (at a tile corner). Taking the four (a0, b0),
  // (a1, b0), (a0, b1), (a1, b1), with a0 = a1 off a column border and b0 = b1 off a row border,
  // counts some tile twice, which an intersection does not mind: no branches. A tile is read as two
  // overlapping vectors, (min x, min y, min z, max x) and (min z, max x, max y, max z): the node's
  // lower bounds are the greatest of the first's lanes 0-2, its upper ones the least of the
  // second's lanes 1-3; the hull takes the least and the greatest of those over the nodes.
  const float* const tiles = reinterpret_cast<const float*>(levels_[0].data());
  constexpr std::size_t kFloats = sizeof(TileBounds) / sizeof(float);
  const unsigned last_a = static_cast<unsigned>(tiles_x_ - 1), last_b = static_cast<unsigned>(tiles_y_ - 1);
  const std::size_t row = static_cast<std::size_t>(tiles_x_) * kFloats;
  using W = sim::WideBaseline;  // four lanes: SSE2 or NEON
  static_assert(W::width == 4, "a tile's bounds are read four floats at a time");
  W::F low = W::set1(kInf), high = W::set1(-kInf);
  for (const Point& p : nodes) {
    // (x - 1) / kTileCells and x / kTileCells, clamped to the grid's tiles (x = 0: tile 0 twice).
    const unsigned x = static_cast<unsigned>(p.x), y = static_cast<unsigned>(p.y);
    const std::size_t a0 = std::min((x - (x > 0)) / kTileCells, last_a) * kFloats, a1 = std::min(x / kTileCells, last_a) * kFloats;
    const std::size_t b0 = std::min((y - (y > 0)) / kTileCells, last_b) * row, b1 = std::min(y / kTileCells, last_b) * row;
    const float *t00 = tiles + b0 + a0, *t10 = tiles + b0 + a1, *t01 = tiles + b1 + a0, *t11 = tiles + b1 + a1;
    const W::F least = W::max_of(W::max_of(W::load(t00), W::load(t10)), W::max_of(W::load(t01), W::load(t11)));
    const W::F greatest = W::min_of(W::min_of(W::load(t00 + 2), W::load(t10 + 2)), W::min_of(W::load(t01 + 2), W::load(t11 + 2)));
    low = W::min_of(low, least), high = W::max_of(high, greatest);
  }
  float lo[4], hi[4];
  W::store(lo, low), W::store(hi, high);
  return {lo[0], lo[1], lo[2], hi[1], hi[2], hi[3]};
}

TileRanges tile_ranges(const NodePositions& p) {
  // The rest grid's spacing: a guess that only has to be finite (and is exact for a rest grid).
  double spacing = (double(world_position(p, 0, p.cols - 1)[0]) - world_position(p, 0, 0)[0]) / (p.cols - 1);
  if (!std::isfinite(spacing)) spacing = 1;
  const int tx = tiles_on(p.cols), ty = tiles_on(p.rows);
  std::vector<TileBounds> tiles(static_cast<std::size_t>(tx) * static_cast<std::size_t>(ty));
  // Row by row (a stream, not tile windows far apart), each row's nodes into its tiles' ranges.
  std::vector<float> x(static_cast<std::size_t>(p.cols)), y(x.size()), z(x.size());
  std::vector<double> lo(3 * static_cast<std::size_t>(tx)), hi(lo.size());
  float largest = 0;
  for (int b = 0; b < ty; ++b) {
    std::fill(lo.begin(), lo.end(), kInf), std::fill(hi.begin(), hi.end(), -kInf);
    for (int row = b * kTileCells; row <= std::min(b * kTileCells + kTileCells, p.rows - 1); ++row) {
      const float row_largest = copy_finite_window(p, row, 0, 1, p.cols, x.data(), y.data(), z.data());
      largest = std::max(largest, row_largest);
      // Deviations in double: exact but for the rest position's rounding (~1e-16 relative).
      const double rest_z = row * spacing;
      for (int a = 0; a < tx; ++a) {
        double* l = &lo[3 * static_cast<std::size_t>(a)];
        double* h = &hi[3 * static_cast<std::size_t>(a)];
        for (int k = a * kTileCells; k <= std::min(a * kTileCells + kTileCells, p.cols - 1); ++k) {
          const double dx = double(x[k]) - k * spacing, dy = y[k], dz = double(z[k]) - rest_z;
          l[0] = std::min(l[0], dx), h[0] = std::max(h[0], dx);
          l[1] = std::min(l[1], dy), h[1] = std::max(h[1], dy);
          l[2] = std::min(l[2], dz), h[2] = std::max(h[2], dz);
        }
      }
    }
    for (int a = 0; a < tx; ++a) {
      const double* l = &lo[3 * static_cast<std::size_t>(a)];
      const double* h = &hi[3 * static_cast<std::size_t>(a)];
      tiles[static_cast<std::size_t>(b) * tx + a] = {down(l[0]), down(l[1]), down(l[2]), up(h[0]), up(h[1]), up(h[2])};
    }
  }
  return TileRanges(p.rows, p.cols, spacing, std::move(tiles), largest);
}

TileRanges tile_ranges(std::span<const TileBounds> u, int rows, int cols, float spacing) {
  const int tx = tiles_on(cols), ty = tiles_on(rows);
  if (u.size() != static_cast<std::size_t>(tx) * static_cast<std::size_t>(ty))
    throw InternalError("tile bounds hold " + std::to_string(u.size()) + " tiles, the grid has " +
                        std::to_string(tx * ty));
  const double h = spacing;
  double extreme[3] = {0, 0, 0};  // the largest |displacement| per component, in world units
  for (std::size_t k = 0; k < u.size(); ++k) {
    const TileBounds& t = u[k];
    for (float v : {t.min_x, t.min_y, t.min_z, t.max_x, t.max_y, t.max_z})
      if (!std::isfinite(v))
        throw InputError("tile " + std::to_string(k) + " of the solver's tile bounds is not finite");
    extreme[0] = std::max({extreme[0], std::abs(t.min_x * h), std::abs(t.max_x * h)});
    extreme[1] = std::max({extreme[1], std::abs(t.min_y * h), std::abs(t.max_y * h)});
    extreme[2] = std::max({extreme[2], std::abs(t.min_z * h), std::abs(t.max_z * h)});
  }
  const double largest = std::max({(cols - 1) * h + extreme[0], extreme[1], (rows - 1) * h + extreme[2]}) * (1 + 1e-6);
  // World x = fl(fl(col + ux) h): two roundings of magnitudes <= largest, so x - col h lies within
  // ux h -+ eps largest (y and z alike); twice that, and outward rounding, for the products here.
  const double slack = 2 * largest * std::numeric_limits<float>::epsilon();
  std::vector<TileBounds> tiles(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) {
    const TileBounds& t = u[k];
    tiles[k] = {down(t.min_x * h - slack), down(t.min_y * h - slack), down(t.min_z * h - slack),
                up(t.max_x * h + slack), up(t.max_y * h + slack), up(t.max_z * h + slack)};
  }
  return TileRanges(rows, cols, h, std::move(tiles), up(largest));
}

}  // namespace pond::lod
