#pragma once
// The longest-edge-bisection (4-8) hierarchy over an R x C grid of any size, in index space:
// x = column, y = row. Everything here depends only on the grid size, so it is built once.
//
// Any size: the rectangle [0, C-1] x [0, R-1] is tiled by dyadic squares (side 2^k, corners at
// multiples of 2^k): C-1 and R-1 are split into powers of two, largest first, so every block
// starts at a multiple of its own size. Each square is two root triangles of ONE global 4-8
// hierarchy (a square's diagonal always runs through its parent square's centre), so a node's
// place in the hierarchy (the hypotenuse it splits, its two parents, its four children) follows
// from its coordinates alone, across tile seams too. Tile corners are always vertices; where a
// small tile's corner lies in the middle of a bigger tile's edge, the bigger tile must be split
// down to it, which the static closure below records.
//
// A mesh of the hierarchy is a set of "active" (split) vertices. It is conforming (no cracks,
// no T-junctions) exactly when the set is closed under "a vertex's parents are active"
// (Lindstrom & Pascucci); the leaves reached from the roots by splitting at active midpoints
// are then the triangles.
#include <array>
#include <cstdint>
#include <vector>

namespace pond::lod {

struct Point {
  int x = 0, y = 0;  // column, row
  friend bool operator==(Point, Point) = default;
};

// A triangle of the hierarchy: a right isosceles triangle with its right angle at `apex` and
// hypotenuse left -> right. (apex, left, right) turns clockwise in the (x = col, y = row) plane,
// which is what makes the rest normal (left - apex) x (right - apex) of the world positions
// (col, 0, row) point to +y.
struct Tri {
  Point apex, left, right;
};

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
  std::uint32_t id(Point p) const {
    return static_cast<std::uint32_t>(p.y) * static_cast<std::uint32_t>(cols_) +
           static_cast<std::uint32_t>(p.x);
  }
  bool inside(Point p) const { return p.x >= 0 && p.y >= 0 && p.x < cols_ && p.y < rows_; }

  // Root triangles, tile by tile, two per tile.
  const std::vector<Tri>& roots() const { return roots_; }
  // Per node: 1 when the node is a vertex of every mesh (tile corners and what they force).
  const std::vector<std::uint8_t>& always_split() const { return always_; }
  const std::vector<std::uint32_t>& always_split_ids() const { return always_ids_; }

  // Only for nodes that are not tile corners.
  static Diamond diamond(Point v);

 private:
  void add_tile(int x0, int y0, int side);
  void force(Point v);
  int rows_, cols_;
  std::vector<Tri> roots_;
  std::vector<std::uint8_t> always_;
  std::vector<std::uint8_t> corner_;
  std::vector<std::uint32_t> always_ids_;
};

// The hypotenuse midpoint of t; false when the hypotenuse is a cell diagonal (no node there).
inline bool midpoint(const Tri& t, Point& m) {
  const int sx = t.left.x + t.right.x, sy = t.left.y + t.right.y;
  if ((sx | sy) & 1) return false;
  m = {sx / 2, sy / 2};
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
