#include "lod/error_bounds.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>

#include <emmintrin.h>  // SSE2: the diagonal vertices four at a time

namespace pond::lod {
namespace {

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

// SSE2 helpers for diagonal_row: four vertices (x0, x0 + 2, x0 + 4, x0 + 6) of one row at a time.
// Lanes 0 and 2 of a, then of b.
__m128 evens(__m128 a, __m128 b) { return _mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0)); }
// c at columns i, i + 2, i + 4, i + 6 (reads i .. i + 7 only).
__m128 every_other(const float* c, std::size_t i) { return evens(_mm_loadu_ps(c + i), _mm_loadu_ps(c + i + 4)); }
// The bounds at ids i, i + 2, i + 4, i + 6: their errors and their least budgets.
void bounds_at(const NestedBound* b, std::size_t i, __m128& error, __m128& least) {
  const auto pair = [&](std::size_t k) { return _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(b + k)); };
  const __m128 t0 = _mm_unpacklo_ps(pair(i), pair(i + 2)), t1 = _mm_unpacklo_ps(pair(i + 4), pair(i + 6));
  error = _mm_movelh_ps(t0, t1);
  least = _mm_movehl_ps(t1, t0);
}
__m128 select(__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); }

// The diagonal ones are the centres (odd x, odd y) of the 2x2 squares. Their four children
// (x -+ 1, y) and (x, y -+ 1) are scale-1 axis vertices, inside the grid whenever the vertex is,
// so the general vertex()'s border checks and child loop go away. Four vertices at a time, their
// squares' diagonals alternating (each lane the scalar formula's operations in its order), then
// one at a time.
void diagonal_row(const Pass& pass, int y) {
  const std::size_t row = static_cast<std::size_t>(pass.cols);
  const NestedBound* bounds = pass.out;
  const int b = y / 2;  // the squares' row index
  const std::size_t at = static_cast<std::size_t>(y) * row;
  // Lanes whose square has the main diagonal: (a + b) even, a = the square's index in the row.
  const __m128 main_lanes = (b & 1) == 0 ? _mm_castsi128_ps(_mm_setr_epi32(-1, 0, -1, 0))
                                         : _mm_castsi128_ps(_mm_setr_epi32(0, -1, 0, -1));
  const __m128 half = _mm_set1_ps(0.5f), slack = _mm_set1_ps(pass.slack), grow = _mm_set1_ps(kBoundGrow);
  int x = 1, a = 0;
  for (; x + 7 < pass.cols; x += 8, a += 4) {
    const std::size_t id = at + static_cast<std::size_t>(x), up = id - row, down = id + row;
    __m128 d2 = _mm_setzero_ps();
    for (const float* c : {pass.x, pass.y, pass.z}) {
      // Ends: (x - 1, y - 1) and (x + 1, y + 1) on a main diagonal, (x + 1, y - 1) and (x - 1, y + 1) else.
      const __m128 up_left = evens(_mm_loadu_ps(c + up - 1), _mm_loadu_ps(c + up + 3));
      const __m128 up_right = _mm_shuffle_ps(_mm_loadu_ps(c + up + 1), _mm_loadu_ps(c + up + 4), _MM_SHUFFLE(3, 1, 2, 0));
      const __m128 down_left = evens(_mm_loadu_ps(c + down - 1), _mm_loadu_ps(c + down + 3));
      const __m128 down_right = _mm_shuffle_ps(_mm_loadu_ps(c + down + 1), _mm_loadu_ps(c + down + 4), _MM_SHUFFLE(3, 1, 2, 0));
      const __m128 e0 = select(main_lanes, up_left, up_right), e1 = select(main_lanes, down_right, down_left);
      const __m128 d = _mm_sub_ps(every_other(c, id), _mm_mul_ps(half, _mm_add_ps(e0, e1)));
      d2 = c == pass.x ? _mm_mul_ps(d, d) : _mm_add_ps(d2, _mm_mul_ps(d, d));
    }
    const __m128 dev = _mm_add_ps(_mm_sqrt_ps(d2), slack);
    __m128 we, wl, ee, el, ne, nl, se, sl;
    bounds_at(bounds, id - 1, we, wl), bounds_at(bounds, id + 1, ee, el);
    bounds_at(bounds, up, ne, nl), bounds_at(bounds, down, se, sl);
    const __m128 worst = _mm_max_ps(_mm_max_ps(we, ee), _mm_max_ps(ne, se));
    const __m128 least = _mm_min_ps(_mm_min_ps(every_other(pass.budget, id), _mm_min_ps(wl, el)), _mm_min_ps(nl, sl));
    const __m128 error = _mm_mul_ps(_mm_add_ps(dev, worst), grow);
    const __m128 lo = _mm_unpacklo_ps(error, least), hi = _mm_unpackhi_ps(error, least);
    _mm_storel_pi(reinterpret_cast<__m64*>(pass.out + id), lo), _mm_storeh_pi(reinterpret_cast<__m64*>(pass.out + id + 2), lo);
    _mm_storel_pi(reinterpret_cast<__m64*>(pass.out + id + 4), hi), _mm_storeh_pi(reinterpret_cast<__m64*>(pass.out + id + 6), hi);
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
      diagonal_row(pass, y - 1);
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
