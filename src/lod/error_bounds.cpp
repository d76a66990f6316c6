#include "lod/error_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pond::lod {
namespace {

// Stored bounds round up by this much: storing a double as float rounds by 6e-8 relative, and the
// bound must never end below the true distance.
constexpr double kBoundGrow = 1 + 1e-6;

struct Pass {
  const GridHierarchy& grid;
  const float *x, *y, *z;
  const float* budget;
  float* bound;
  float* min_budget;
  const std::uint8_t* always;

  double deviation(std::uint32_t v, std::uint32_t e0, std::uint32_t e1) const {
    const double dx = x[v] - 0.5 * (double(x[e0]) + x[e1]);
    const double dy = y[v] - 0.5 * (double(y[e0]) + y[e1]);
    const double dz = z[v] - 0.5 * (double(z[e0]) + z[e1]);
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }

  // One split vertex with its children (coordinates; those outside the grid are skipped).
  void vertex(Point v, const Point* children, int child_count) const {
    const std::uint32_t id = grid.id(v);
    if (always[id]) {
      bound[id] = std::numeric_limits<float>::infinity();
      min_budget[id] = budget[id];
      return;
    }
    const Diamond d = GridHierarchy::diamond(v);
    double worst_child = 0;
    float least = budget[id];
    for (int k = 0; k < child_count; ++k) {
      if (!grid.inside(children[k])) continue;
      const std::uint32_t c = grid.id(children[k]);
      worst_child = std::max(worst_child, double(bound[c]));
      least = std::min(least, min_budget[c]);
    }
    bound[id] = static_cast<float>((deviation(id, grid.id(d.end0), grid.id(d.end1)) + worst_child) *
                                   kBoundGrow);
    min_budget[id] = least;
  }
};

}  // namespace

void nested_bounds(const GridHierarchy& grid, const NodePositions& p, const float* budget,
                   float* bound, float* min_budget) {
  const Pass pass{grid, p.x, p.y, p.z, budget, bound, min_budget, grid.always_split().data()};
  const int rows = grid.rows(), cols = grid.cols();
  const int extent = std::max(rows, cols);
  for (int h = 1; h < extent; h *= 2) {
    const int q = h / 2, step = 2 * h;
    // Axis-aligned hypotenuses of length 2h: horizontal (x = h mod 2h, y = 0 mod 2h) and vertical
    // (x = 0 mod 2h, y = h mod 2h). Their children are diagonal centres of scale h/2.
    for (int pass_kind = 0; pass_kind < 2; ++pass_kind) {
      const int x_start = pass_kind == 0 ? h : 0, y_start = pass_kind == 0 ? 0 : h;
      for (int y = y_start; y < rows; y += step)
        for (int x = x_start; x < cols; x += step) {
          const Point children[4] = {{x - q, y - q}, {x + q, y - q}, {x - q, y + q}, {x + q, y + q}};
          pass.vertex({x, y}, children, q > 0 ? 4 : 0);
        }
    }
    // Diagonal hypotenuses of the squares of side 2h: children are that square's edge midpoints.
    for (int y = h; y < rows; y += step)
      for (int x = h; x < cols; x += step) {
        const Point children[4] = {{x - h, y}, {x + h, y}, {x, y - h}, {x, y + h}};
        pass.vertex({x, y}, children, 4);
      }
  }
}

}  // namespace pond::lod
