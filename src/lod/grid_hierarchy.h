#pragma once
// The longest-edge-bisection (4-8) hierarchy over an R x C grid of any size, in index space:
// x = column, y = row. Everything here depends only on the grid size, so it is built once.
//
// Any size: the hierarchy lives on a padded domain, [0, 2^a] x [0, 2^b] with 2^a >= C-1 and
// 2^b >= R-1, tiled by squares of side 2^min(a, b). Each square is two root triangles of ONE
// global 4-8 hierarchy (a square's diagonal always runs through its parent square's centre), so a
// node's place in the hierarchy (the hypotenuse it splits, its two parents, its four children)
// follows from its coordinates alone. Nodes of the padded domain outside the grid are virtual:
// a triangle reaching past the grid is clipped to it (clip_to_grid), which gives a convex polygon
// whose corners are all grid nodes (edges run at 0, 45 and 90 degrees and the grid's borders lie
// on integer lines), and the polygon is drawn as a fan. A triangle wholly outside is dropped.
//
// A mesh of the hierarchy is a set of "active" (split) vertices. It is conforming (no cracks,
// no T-junctions) exactly when the set is closed under "a vertex's parents are active"
// (Lindstrom & Pascucci); the leaves reached from the roots by splitting at active midpoints
// are then the triangles.
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace pond::lod {

struct Point {
  // Column, row. Not initialized by default: the builder makes a GridPolygon (eight points) for
  // every triangle it tests, and zeroing them showed in its instruction counts.
  int x, y;
  friend bool operator==(Point, Point) = default;
};

// A triangle of the hierarchy: a right isosceles triangle with its right angle at `apex` and
// hypotenuse left -> right. (apex, left, right) turns clockwise in the (x = col, y = row) plane,
// which is what makes the rest normal (left - apex) x (right - apex) of the world positions
// (col, 0, row) point to +y.
struct Tri {
  Point apex, left, right;
};

// The columns [x0, x1] and rows [y0, y1] a triangle spans.
struct CellBox {
  int x0, x1, y0, y1;
};
inline CellBox box_of(const Tri& t) {
  return {std::min(t.apex.x, std::min(t.left.x, t.right.x)), std::max(t.apex.x, std::max(t.left.x, t.right.x)),
          std::min(t.apex.y, std::min(t.left.y, t.right.y)), std::max(t.apex.y, std::max(t.left.y, t.right.y))};
}

// The diamond a split vertex is the centre of: the hypotenuse it halves and the apexes of the
// (up to) two triangles sharing it. Parents may lie outside the grid (border diamonds).
struct Diamond {
  Point end0, end1;
  std::array<Point, 2> parents;
};

class GridHierarchy {
 public:
  GridHierarchy(int rows, int cols);  // rows, cols >= 2

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  // Grid nodes: index row * cols + col.
  std::uint32_t id(Point p) const {
    return static_cast<std::uint32_t>(p.y) * static_cast<std::uint32_t>(cols_) +
           static_cast<std::uint32_t>(p.x);
  }
  bool inside(Point p) const { return p.x >= 0 && p.y >= 0 && p.x < cols_ && p.y < rows_; }
  // Nodes of the padded domain (grid nodes and virtual ones).
  std::size_t domain_nodes() const {
    return static_cast<std::size_t>(domain_rows_) * static_cast<std::size_t>(domain_cols_);
  }
  std::uint32_t domain_id(Point p) const {
    return static_cast<std::uint32_t>(p.y) * static_cast<std::uint32_t>(domain_cols_) +
           static_cast<std::uint32_t>(p.x);
  }
  // The node of a domain id (by a multiply, as copy_nodes() finds a row: (id + 0.5) / cols lies at
  // least 2^-17 from an integer, and double errs far less).
  Point domain_point(std::uint32_t id) const {
    const auto y = static_cast<std::uint32_t>((static_cast<double>(id) + 0.5) * inverse_domain_cols_);
    return {static_cast<int>(id - y * static_cast<std::uint32_t>(domain_cols_)), static_cast<int>(y)};
  }
  bool in_domain(Point p) const {
    return p.x >= 0 && p.y >= 0 && p.x < domain_cols_ && p.y < domain_rows_;
  }
  // All three vertices are grid nodes (then so is every node of the triangle).
  bool within_grid(const Tri& t) const {
    return (t.apex.x | t.apex.y | t.left.x | t.left.y | t.right.x | t.right.y) >= 0 &&
           std::max({t.apex.x, t.left.x, t.right.x}) < cols_ && std::max({t.apex.y, t.left.y, t.right.y}) < rows_;
  }
  // The same for a triangle of the hierarchy (its corners in the domain): always where the grid is
  // its whole domain (sides 2^k + 1), with no test.
  bool hierarchy_tri_within_grid(const Tri& t) const { return grid_is_domain_ || within_grid(t); }

  // Root triangles, tile by tile, two per tile.
  const std::vector<Tri>& roots() const { return roots_; }
  // Domain ids of the nodes that are vertices of every mesh (the tile corners).
  const std::vector<std::uint32_t>& always_split_ids() const { return always_ids_; }

  // Only for nodes that are not tile corners.
  static Diamond diamond(Point v);

 private:
  void add_tile(int x0, int y0, int side);
  int rows_, cols_;
  int domain_rows_ = 0, domain_cols_ = 0;
  double inverse_domain_cols_ = 0;
  bool grid_is_domain_ = false;
  std::vector<Tri> roots_;
  std::vector<std::uint32_t> always_ids_;
};

// The part of t inside the grid [0, cols-1] x [0, rows-1], as a convex polygon in t's (clockwise)
// order without repeated corners; fewer than 3 corners when t only touches the grid or misses it.
// Holds up to 7 corners.
struct GridPolygon {
  Point corner[8];
  int count = 0;
  std::span<const Point> corners() const { return {corner, static_cast<std::size_t>(count)}; }
};
GridPolygon clip_to_grid(const Tri& t, int rows, int cols);

// The hypotenuse midpoint of t; false when the hypotenuse is a cell diagonal (no node there).
inline bool midpoint(const Tri& t, Point& m) {
  const int sx = t.left.x + t.right.x, sy = t.left.y + t.right.y;
  if ((sx | sy) & 1) return false;
  m = {sx >> 1, sy >> 1};  // halves of even numbers, negative ones too: no rounding to correct
  return true;
}

// The two children of t split at its midpoint m; both keep the clockwise orientation.
inline Tri child_left(const Tri& t, Point m) { return {m, t.apex, t.left}; }   // holds t.left
inline Tri child_right(const Tri& t, Point m) { return {m, t.right, t.apex}; }  // holds t.right

// The triangle with apex `a` on hypotenuse e0-e1, oriented clockwise.
inline Tri oriented(Point a, Point e0, Point e1) {
  const long long cross = static_cast<long long>(e0.x - a.x) * (e1.y - a.y) -
                          static_cast<long long>(e0.y - a.y) * (e1.x - a.x);
  return cross < 0 ? Tri{a, e0, e1} : Tri{a, e1, e0};
}

}  // namespace pond::lod
