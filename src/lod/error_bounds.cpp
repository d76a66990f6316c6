#include "lod/error_bounds.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>

#include "sim/wide_baseline.h"

namespace pond::lod {
namespace {

using sim::WideBaseline;  // the diagonal vertices a vector at a time: SSE2 or NEON, four

// Each sum rounds by at most 6e-8 relative; growing by 1e-5 keeps every bound above the exact
// value it stands for.
constexpr float kBoundGrow = 1 + 1e-5f;

// One scale's pass over the vertices of one class: ids step by `dx` along a row and `dy` between
// rows; the hypotenuse ends are id -+ `e` (inside the grid: the loops stop before vertices whose
// hypotenuse would leave it); the children are at offsets child[k] (all
// four inside the grid unless the vertex is within `reach` of the border, then checked one by one).
struct Pass {
  const float *x, *y, *z;
  const float* budget;
  NestedBound* out;
  int rows, cols;
  float slack;

  // In float for speed; `slack` (from the largest coordinate) covers its rounding, so the result
  // never falls below the exact distance.
  float deviation(std::size_t v, std::size_t e0, std::size_t e1) const {
    const float dx = x[v] - 0.5f * (x[e0] + x[e1]);
    const float dy = y[v] - 0.5f * (y[e0] + y[e1]);
    const float dz = z[v] - 0.5f * (z[e0] + z[e1]);
    return std::sqrt(dx * dx + dy * dy + dz * dz) + slack;
  }

  // Vertex (vx, vy) with hypotenuse ends id -+ e and children at the given offsets (cx, cy).
  void vertex(int vx, int vy, std::ptrdiff_t e, const int (*child)[2], int child_count,
              int reach) const {
    const std::size_t id = static_cast<std::size_t>(vy) * static_cast<std::size_t>(cols) +
                           static_cast<std::size_t>(vx);
    const bool interior = vx >= reach && vy >= reach && vx + reach < cols && vy + reach < rows;
    if (interior && child_count == 4) {  // most vertices: no checks, no loop
      const std::ptrdiff_t row = cols;
      const NestedBound c0 = out[id + child[0][1] * row + child[0][0]];
      const NestedBound c1 = out[id + child[1][1] * row + child[1][0]];
      const NestedBound c2 = out[id + child[2][1] * row + child[2][0]];
      const NestedBound c3 = out[id + child[3][1] * row + child[3][0]];
      const float worst = std::max(std::max(c0.error, c1.error), std::max(c2.error, c3.error));
      const float least = std::min(std::min(budget[id], std::min(c0.min_budget, c1.min_budget)),
                                   std::min(c2.min_budget, c3.min_budget));
      const float dev = deviation(id, id - static_cast<std::size_t>(e), id + static_cast<std::size_t>(e));
      out[id] = {(dev + worst) * kBoundGrow, least};
      return;
    }
    float worst_child = 0, least = budget[id];
    for (int k = 0; k < child_count; ++k) {
      const int cx = vx + child[k][0], cy = vy + child[k][1];
      if (!interior && (cx < 0 || cy < 0 || cx >= cols || cy >= rows)) continue;
      const std::size_t c = static_cast<std::size_t>(cy) * static_cast<std::size_t>(cols) +
                            static_cast<std::size_t>(cx);
      worst_child = std::max(worst_child, out[c].error);
      least = std::min(least, out[c].min_budget);
    }
    const float dev = deviation(id, id - static_cast<std::size_t>(e), id + static_cast<std::size_t>(e));
    out[id] = {(dev + worst_child) * kBoundGrow, least};
  }
};

// Scale 1, row by row. Horizontal hypotenuses (even y, odd x) and vertical ones (odd y, even x)
// have no children: plain loops over contiguous triples.
void horizontal_row(const Pass& pass, int y) {
  const std::size_t r0 = static_cast<std::size_t>(y) * static_cast<std::size_t>(pass.cols);
  for (int x = 1; x + 1 < pass.cols; x += 2) {
    const std::size_t id = r0 + static_cast<std::size_t>(x);
    pass.out[id] = {pass.deviation(id, id - 1, id + 1) * kBoundGrow, pass.budget[id]};
  }
}

void vertical_row(const Pass& pass, int y) {
  const std::size_t row = static_cast<std::size_t>(pass.cols);
  const std::size_t r0 = static_cast<std::size_t>(y) * row;
  for (int x = 0; x < pass.cols; x += 2) {
    const std::size_t id = r0 + static_cast<std::size_t>(x);
    pass.out[id] = {pass.deviation(id, id - row, id + row) * kBoundGrow, pass.budget[id]};
  }
}

// Lanes alternately true and false, from any entry on: the squares of a row of them with the main
// diagonal, from entry (a + b) & 1 (see diagonal_row).
constexpr std::uint32_t kAlternating[17] = {~0u, 0, ~0u, 0, ~0u, 0, ~0u, 0, ~0u, 0, ~0u, 0, ~0u, 0, ~0u, 0, ~0u};

// The diagonal ones are the centres (odd x, odd y) of the 2x2 squares. Their four children
// (x -+ 1, y) and (x, y -+ 1) are scale-1 axis vertices, inside the grid whenever the vertex is,
// so the general vertex()'s border checks and child loop go away. W::width vertices at a time
// (x, x + 2, ...: every other column, each vector load pair deinterleaved), their squares'
// diagonals alternating (each lane the scalar formula's operations in its order), then one at a time.
template <class W>
void diagonal_row(const Pass& pass, int y) {
  using F = typename W::F;
  const std::size_t row = static_cast<std::size_t>(pass.cols);
  const NestedBound* bounds = pass.out;
  const float* const bound_floats = reinterpret_cast<const float*>(bounds);
  const int b = y / 2;  // the squares' row index
  const std::size_t at = static_cast<std::size_t>(y) * row;
  const F half = W::set1(0.5f), slack = W::set1(pass.slack), grow = W::set1(kBoundGrow);
  const int span = 2 * W::width;  // the columns a vector of vertices covers
  // Lanes whose square has the main diagonal: (a + k + b) even, a + k = the square's index in the
  // row (with an even width, the same lanes in every vector).
  typename W::M main_lanes = W::load_mask(kAlternating + (b & 1));
  int x = 1, a = 0;
  for (; x + span - 1 < pass.cols; x += span, a += W::width) {
    if constexpr (W::width % 2 != 0) main_lanes = W::load_mask(kAlternating + ((a + b) & 1));
    const std::size_t id = at + static_cast<std::size_t>(x), up = id - row, down = id + row;
    F d2 = W::set1(0);
    for (const float* c : {pass.x, pass.y, pass.z}) {
      // Ends: (x - 1, y - 1) and (x + 1, y + 1) on a main diagonal, (x + 1, y - 1) and (x - 1, y + 1) else.
      F up_left, up_right, down_left, down_right, here, unused;
      W::load_evens_odds(c + up - 1, up_left, unused), W::load_evens_odds(c + up, unused, up_right);
      W::load_evens_odds(c + down - 1, down_left, unused), W::load_evens_odds(c + down, unused, down_right);
      W::load_evens_odds(c + id, here, unused);
      const F e0 = W::select(main_lanes, up_left, up_right), e1 = W::select(main_lanes, down_right, down_left);
      const F d = W::sub(here, W::mul(half, W::add(e0, e1)));
      d2 = c == pass.x ? W::mul(d, d) : W::add(d2, W::mul(d, d));
    }
    const F dev = W::add(W::sqrt(d2), slack);
    // The bounds (error, least budget) at ids i, i + 2, ...: pairs of floats four apart.
    F we, wl, ee, el, ne, nl, se, sl, budget, unused;
    W::load_pairs(bound_floats + 2 * (id - 1), we, wl), W::load_pairs(bound_floats + 2 * (id + 1), ee, el);
    W::load_pairs(bound_floats + 2 * up, ne, nl), W::load_pairs(bound_floats + 2 * down, se, sl);
    W::load_evens_odds(pass.budget + id, budget, unused);
    const F worst = W::max_of(W::max_of(we, ee), W::max_of(ne, se));
    const F least = W::min_of(W::min_of(budget, W::min_of(wl, el)), W::min_of(nl, sl));
    W::store_pairs(reinterpret_cast<float*>(pass.out + id), W::mul(W::add(dev, worst), grow), least);
  }
  for (; x + 1 < pass.cols; x += 2, ++a) {
    const std::size_t id = at + static_cast<std::size_t>(x);
    const std::size_t e = ((a + b) & 1) == 0 ? row + 1 : row - 1;  // main or anti diagonal
    const NestedBound w = bounds[id - 1], east = bounds[id + 1];
    const NestedBound n = bounds[id - row], s = bounds[id + row];
    const float worst_child = std::max(std::max(w.error, east.error), std::max(n.error, s.error));
    const float least = std::min(std::min(pass.budget[id], std::min(w.min_budget, east.min_budget)),
                                 std::min(n.min_budget, s.min_budget));
    pass.out[id] = {(pass.deviation(id, id - e, id + e) + worst_child) * kBoundGrow, least};
  }
}

// All of scale 1 (three quarters of the vertices) in one sweep down the rows, so that each row is
// still in cache when the next needs it: even row y's horizontal vertices, then the odd row above,
// whose vertical vertices need rows y - 2 .. y and whose diagonal ones need those and the
// horizontal vertices of rows y - 2 and y.
void scale_one(const Pass& pass) {
  for (int y = 0; y < pass.rows; y += 2) {
    horizontal_row(pass, y);
    if (y >= 2) {
      vertical_row(pass, y - 1);
      diagonal_row<WideBaseline>(pass, y - 1);
    }
  }
}

}  // namespace

void nested_bounds(const GridHierarchy& grid, const NodePositions& p, float largest,
                   const float* budget, NestedBound* bounds) {
  const int rows = grid.rows(), cols = grid.cols();
  // Float rounding of a deviation: each of its ~6 operations errs by at most half an ulp of the
  // largest magnitude involved (<= 2 * largest), so 16 ulps of `largest` is a safe slack.
  const float slack = 16 * largest * std::numeric_limits<float>::epsilon();
  const Pass pass{p.x, p.y, p.z, budget, bounds, rows, cols, slack};
  const std::ptrdiff_t row = cols;
  const int extent = std::max(rows, cols);
  for (int h = 1; h < extent; h *= 2) {
    const int q = h / 2, step = 2 * h;
    // Axis-aligned hypotenuses of length 2h: horizontal (x = h mod 2h, y = 0 mod 2h) and vertical
    // (x = 0 mod 2h, y = h mod 2h). Their children are the diagonal centres of scale h/2 around.
    const int axis_children[4][2] = {{-q, -q}, {q, -q}, {-q, q}, {q, q}};
    if (h == 1) {
      scale_one(pass);
      continue;
    }
    // Diagonal hypotenuses of the squares of side 2h (main diagonal when the square's index
    // parity is even, see GridHierarchy::diamond): children are that square's edge midpoints.
    const int diag_children[4][2] = {{-h, 0}, {h, 0}, {0, -h}, {0, h}};
    // One sweep down the rows, as at scale 1: row y's horizontal vertices, then the row h above,
    // whose vertical vertices' ends and children are done and whose diagonal ones need those
    // and the horizontal vertices of rows y - 2h and y.
    for (int y = 0; y < rows; y += step) {
      for (int x = h; x + h < cols; x += step) pass.vertex(x, y, h, axis_children, 4, q);
      if (y < step) continue;
      const int above = y - h, b = above / step;  // b: the squares' row index
      for (int x = 0; x < cols; x += step) pass.vertex(x, above, h * row, axis_children, 4, q);
      for (int x = h, a = 0; x + h < cols; x += step, ++a)
        pass.vertex(x, above, ((a + b) & 1) == 0 ? h * row + h : h * row - h, diag_children, 4, h);
    }
  }
}

}  // namespace pond::lod
