#include "lod/grid_hierarchy.h"

#include <algorithm>
#include <bit>
#include <string>

#include "core/errors.h"

namespace pond::lod {

Diamond GridHierarchy::diamond(Point v) {
  // h = 2^k is v's scale, the lowest bit of either coordinate. The quotients below are exact (h
  // divides both coordinates, 2h divides v - h where v / h is odd), so shifts give them.
  const int k = std::countr_zero(static_cast<unsigned>(v.x | v.y)), h = 1 << k;
  const bool x_odd = (v.x >> k) & 1, y_odd = (v.y >> k) & 1;
  Diamond d;
  if (x_odd && y_odd) {
    // Centre of the square [x-h, x+h] x [y-h, y+h]: its diagonal runs through the parent
    // square's centre, which picks main or anti diagonal by the square's parity at its scale.
    const bool main = ((((v.x - h) >> (k + 1)) + ((v.y - h) >> (k + 1))) & 1) == 0;
    if (main) {
      d.end0 = {v.x - h, v.y - h}, d.end1 = {v.x + h, v.y + h};
      d.parents = {Point{v.x - h, v.y + h}, Point{v.x + h, v.y - h}};
    } else {
      d.end0 = {v.x - h, v.y + h}, d.end1 = {v.x + h, v.y - h};
      d.parents = {Point{v.x - h, v.y - h}, Point{v.x + h, v.y + h}};
    }
  } else if (x_odd) {  // horizontal hypotenuse
    d.end0 = {v.x - h, v.y}, d.end1 = {v.x + h, v.y};
    d.parents = {Point{v.x, v.y - h}, Point{v.x, v.y + h}};
  } else {  // vertical hypotenuse
    d.end0 = {v.x, v.y - h}, d.end1 = {v.x, v.y + h};
    d.parents = {Point{v.x - h, v.y}, Point{v.x + h, v.y}};
  }
  return d;
}

GridHierarchy::GridHierarchy(int rows, int cols) : rows_(rows), cols_(cols) {
  if (rows < 2 || cols < 2 || rows > (1 << 16) || cols > (1 << 16))
    throw InternalError("LOD grid must be between 2 x 2 and 65536 x 65536 nodes, got " +
                                std::to_string(rows) + " x " + std::to_string(cols));
  const int wide = std::bit_ceil(static_cast<unsigned>(cols - 1));
  const int high = std::bit_ceil(static_cast<unsigned>(rows - 1));
  domain_cols_ = wide + 1, domain_rows_ = high + 1;
  inverse_domain_cols_ = 1.0 / domain_cols_;
  grid_is_domain_ = domain_cols_ == cols && domain_rows_ == rows;
  const int side = std::min(wide, high);
  for (int y = 0; y < high; y += side)
    for (int x = 0; x < wide; x += side) add_tile(x, y, side);
  std::sort(always_ids_.begin(), always_ids_.end());
  always_ids_.erase(std::unique(always_ids_.begin(), always_ids_.end()), always_ids_.end());
}

void GridHierarchy::add_tile(int x0, int y0, int side) {
  const Point a{x0, y0}, b{x0 + side, y0}, c{x0, y0 + side}, d{x0 + side, y0 + side};
  for (Point p : {a, b, c, d}) always_ids_.push_back(domain_id(p));
  const bool main = (((x0 / side) + (y0 / side)) & 1) == 0;
  if (main) {  // diagonal a-d
    roots_.push_back(oriented(b, a, d));
    roots_.push_back(oriented(c, a, d));
  } else {  // diagonal b-c
    roots_.push_back(oriented(a, b, c));
    roots_.push_back(oriented(d, b, c));
  }
}

namespace {

// Sutherland-Hodgman against one border: keeps the side where sign * (coordinate - limit) <= 0.
// Crossings are exact integers: edges run at 0, 45 or 90 degrees.
int clip_against(const Point* in, int n, Point* out, bool vertical_line, int limit) {
  int m = 0;
  const auto excess = [&](Point p) { return (vertical_line ? p.x : p.y) - limit; };
  for (int k = 0; k < n; ++k) {
    const Point a = in[k], b = in[(k + 1) % n];
    const int ea = excess(a), eb = excess(b);
    if (ea <= 0) out[m++] = a;
    if ((ea < 0 && eb > 0) || (ea > 0 && eb < 0)) {
      if (vertical_line)
        out[m++] = {limit, a.y + (b.y - a.y) / (b.x - a.x) * (limit - a.x)};
      else
        out[m++] = {a.x + (b.x - a.x) / (b.y - a.y) * (limit - a.y), limit};
    }
  }
  return m;
}

}  // namespace

GridPolygon clip_to_grid(const Tri& t, int rows, int cols) {
  Point first[8] = {t.apex, t.left, t.right};
  Point second[8];
  // The padded domain only reaches past the right and the far border.
  const int n1 = clip_against(first, 3, second, true, cols - 1);
  const int n2 = clip_against(second, n1, first, false, rows - 1);
  GridPolygon poly;
  for (int k = 0; k < n2; ++k) {
    const Point p = first[k];
    if (poly.count > 0 && poly.corner[poly.count - 1] == p) continue;
    poly.corner[poly.count++] = p;
  }
  while (poly.count > 1 && poly.corner[poly.count - 1] == poly.corner[0]) --poly.count;
  // A polygon of no area (t touches the grid along a border) is no polygon.
  long long twice_area = 0;
  for (int k = 0; k < poly.count; ++k) {
    const Point a = poly.corner[k], b = poly.corner[(k + 1) % poly.count];
    twice_area += static_cast<long long>(a.x) * b.y - static_cast<long long>(b.x) * a.y;
  }
  if (twice_area == 0) poly.count = 0;
  return poly;
}

}  // namespace pond::lod
