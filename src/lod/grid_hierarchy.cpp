#include "lod/grid_hierarchy.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pond::lod {
namespace {

// n split into powers of two, largest first: 49 -> {32, 16, 1}.
std::vector<int> power_of_two_parts(int n) {
  std::vector<int> parts;
  for (int bit = 30; bit >= 0; --bit)
    if (n & (1 << bit)) parts.push_back(1 << bit);
  return parts;
}

int lowest_bit(int v) { return v & -v; }

}  // namespace

Diamond GridHierarchy::diamond(Point v) {
  const int h = lowest_bit(v.x | v.y);
  const bool x_odd = (v.x / h) & 1, y_odd = (v.y / h) & 1;
  Diamond d;
  if (x_odd && y_odd) {
    // Centre of the square [x-h, x+h] x [y-h, y+h]: its diagonal runs through the parent
    // square's centre, which picks main or anti diagonal by the square's parity at its scale.
    const bool main = ((((v.x - h) / (2 * h)) + ((v.y - h) / (2 * h))) & 1) == 0;
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
  if (rows < 2 || cols < 2 || static_cast<long long>(rows) * cols > (1ll << 31))
    throw std::invalid_argument("LOD grid must be at least 2 x 2 and below 2^31 nodes, got " +
                                std::to_string(rows) + " x " + std::to_string(cols));
  const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  always_.assign(n, 0);
  corner_.assign(n, 0);
  int y0 = 0;
  for (int hy : power_of_two_parts(rows - 1)) {
    int x0 = 0;
    for (int wx : power_of_two_parts(cols - 1)) {
      const int side = std::min(hy, wx);
      for (int y = y0; y < y0 + hy; y += side)
        for (int x = x0; x < x0 + wx; x += side) add_tile(x, y, side);
      x0 += wx;
    }
    y0 += hy;
  }
  // A tile corner inside a bigger neighbour's edge: the neighbour's triangles must split down to
  // it, i.e. the corner's parents (and theirs) are always active.
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x)
      if (corner_[id({x, y})] && (x | y) != 0)
        for (Point p : diamond({x, y}).parents)
          if (inside(p)) force(p);
  for (std::uint32_t k = 0; k < always_.size(); ++k)
    if (always_[k]) always_ids_.push_back(k);
}

void GridHierarchy::add_tile(int x0, int y0, int side) {
  const Point a{x0, y0}, b{x0 + side, y0}, c{x0, y0 + side}, d{x0 + side, y0 + side};
  for (Point p : {a, b, c, d}) corner_[id(p)] = always_[id(p)] = 1;
  const bool main = (((x0 / side) + (y0 / side)) & 1) == 0;
  if (main) {  // diagonal a-d
    roots_.push_back(oriented(b, a, d));
    roots_.push_back(oriented(c, a, d));
  } else {  // diagonal b-c
    roots_.push_back(oriented(a, b, c));
    roots_.push_back(oriented(d, b, c));
  }
}

void GridHierarchy::force(Point v) {
  if (always_[id(v)]) return;
  always_[id(v)] = 1;
  for (Point p : diamond(v).parents)
    if (inside(p)) force(p);
}

}  // namespace pond::lod
