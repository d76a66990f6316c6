#include "lod/triangle_scan.h"

#include <algorithm>
#include <climits>
#include <limits>

#include <emmintrin.h>  // SSE2: the row scan, four nodes at a time

namespace pond::lod {
namespace {

// The columns where each row meets the closed triangle. The edges of hierarchy triangles run at
// 0, 45 or 90 degrees, so every crossing is an integer column: x = x_at_y0 + slope * (y - y0).
class RowSpans {
 public:
  explicit RowSpans(const Tri& t) {
    const Point v[3] = {t.apex, t.left, t.right};
    for (int k = 0; k < 3; ++k) {
      const Point a = v[k], b = v[(k + 1) % 3];
      Edge& e = edges_[k];
      e.flat = a.y == b.y;
      e.y_low = std::min(a.y, b.y), e.y_high = std::max(a.y, b.y);
      e.x_low = std::min(a.x, b.x), e.x_high = std::max(a.x, b.x);
      e.slope = e.flat ? 0 : (b.x - a.x) / (b.y - a.y);
      e.x0 = a.x - e.slope * a.y;
    }
  }
  bool span(int y, int& x0, int& x1) const {
    x0 = INT_MAX, x1 = INT_MIN;
    for (const Edge& e : edges_) {
      if (y < e.y_low || y > e.y_high) continue;
      if (e.flat) {
        x0 = std::min(x0, e.x_low), x1 = std::max(x1, e.x_high);
      } else {
        const int x = e.x0 + e.slope * y;
        x0 = std::min(x0, x), x1 = std::max(x1, x);
      }
    }
    return x0 <= x1;
  }

 private:
  struct Edge {
    bool flat;
    int y_low, y_high, x_low, x_high, slope, x0;
  };
  Edge edges_[3];
};

// One row's interpolation: the weights of left and right at the row's first node and their
// steps per column, the apex and the legs in world space, and the rounding slack.
struct RowPlane {
  float u0, w0, du, dw;
  float ax, ay, az, lx3, ly3, lz3, rx3, ry3, rz3;
  float slack;
};

struct RowVerdict {
  bool over;   // a node is over its budget for sure
  bool close;  // a node is so near its budget that float cannot tell
};

// The nodes k = 0 .. len-1 of a row, four at a time (SSE2). The last group's lanes past the row
// read the following nodes (or the arrays' padding) and are masked out, so there is no scalar
// tail. Each lane does the scalar formula's operations in the same order: the same bits.
RowVerdict scan_row(const float* px, const float* py, const float* pz, const float* pb, int len,
                    const RowPlane& r) {
  const __m128 lanes = _mm_setr_ps(0, 1, 2, 3);
  const __m128 u0 = _mm_set1_ps(r.u0), w0 = _mm_set1_ps(r.w0);
  const __m128 du = _mm_set1_ps(r.du), dw = _mm_set1_ps(r.dw);
  const __m128 ax = _mm_set1_ps(r.ax), ay = _mm_set1_ps(r.ay), az = _mm_set1_ps(r.az);
  const __m128 lx = _mm_set1_ps(r.lx3), ly = _mm_set1_ps(r.ly3), lz = _mm_set1_ps(r.lz3);
  const __m128 rx = _mm_set1_ps(r.rx3), ry = _mm_set1_ps(r.ry3), rz = _mm_set1_ps(r.rz3);
  const __m128 slack = _mm_set1_ps(r.slack), zero = _mm_setzero_ps();
  const __m128 grow = _mm_set1_ps(1 + 1e-6f), shrink = _mm_set1_ps(1 - 1e-6f);
  const __m128 end = _mm_set1_ps(static_cast<float>(len));
  __m128 over = zero, close = zero;
  for (int k = 0; k < len; k += 4) {
    const __m128 kf = _mm_add_ps(_mm_set1_ps(static_cast<float>(k)), lanes);  // exact integers
    const __m128 live = _mm_cmplt_ps(kf, end);
    const __m128 u = _mm_add_ps(u0, _mm_mul_ps(kf, du)), w = _mm_add_ps(w0, _mm_mul_ps(kf, dw));
    const __m128 ex = _mm_sub_ps(_mm_loadu_ps(px + k),
                                 _mm_add_ps(_mm_add_ps(ax, _mm_mul_ps(u, lx)), _mm_mul_ps(w, rx)));
    const __m128 ey = _mm_sub_ps(_mm_loadu_ps(py + k),
                                 _mm_add_ps(_mm_add_ps(ay, _mm_mul_ps(u, ly)), _mm_mul_ps(w, ry)));
    const __m128 ez = _mm_sub_ps(_mm_loadu_ps(pz + k),
                                 _mm_add_ps(_mm_add_ps(az, _mm_mul_ps(u, lz)), _mm_mul_ps(w, rz)));
    const __m128 e2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(ex, ex), _mm_mul_ps(ey, ey)), _mm_mul_ps(ez, ez));
    const __m128 b = _mm_loadu_ps(pb + k);
    const __m128 high = _mm_add_ps(b, slack), low = _mm_max_ps(_mm_sub_ps(b, slack), zero);
    over = _mm_or_ps(over, _mm_and_ps(live, _mm_cmpgt_ps(e2, _mm_mul_ps(_mm_mul_ps(high, high), grow))));
    close = _mm_or_ps(close, _mm_and_ps(live, _mm_cmpgt_ps(e2, _mm_mul_ps(_mm_mul_ps(low, low), shrink))));
  }
  return {_mm_movemask_ps(over) != 0, _mm_movemask_ps(close) != 0};
}

}  // namespace

namespace {

// The same test in double, for triangles the float pass cannot decide: every node is then
// judged within 1e-13 relative, far inside the budgets' own 1e-5 margin.
bool within_budget_double(const GridHierarchy& grid, const NodePositions& p, const float* budget,
                          const Tri& t) {
  const int lx = t.left.x - t.apex.x, ly = t.left.y - t.apex.y;
  const int rx = t.right.x - t.apex.x, ry = t.right.y - t.apex.y;
  const double inv_len2 = 1.0 / (double(lx) * lx + double(ly) * ly);
  const std::uint32_t a = grid.id(t.apex), l = grid.id(t.left), r = grid.id(t.right);
  const double ax = p.x[a], ay = p.y[a], az = p.z[a];
  const double lx3 = p.x[l] - ax, ly3 = p.y[l] - ay, lz3 = p.z[l] - az;
  const double rx3 = p.x[r] - ax, ry3 = p.y[r] - ay, rz3 = p.z[r] - az;
  const int y0 = std::min({t.apex.y, t.left.y, t.right.y});
  const int y1 = std::max({t.apex.y, t.left.y, t.right.y});
  const std::size_t cols = static_cast<std::size_t>(grid.cols());
  const RowSpans spans(t);
  for (int y = y0; y <= y1; ++y) {
    int x0, x1;
    if (!spans.span(y, x0, x1)) continue;
    const int dy = y - t.apex.y;
    for (int x = x0; x <= x1; ++x) {
      const int dx = x - t.apex.x;
      const double u = (double(dx) * lx + double(dy) * ly) * inv_len2;
      const double w = (double(dx) * rx + double(dy) * ry) * inv_len2;
      const std::size_t n = static_cast<std::size_t>(y) * cols + static_cast<std::size_t>(x);
      const double ex = p.x[n] - (ax + u * lx3 + w * rx3);
      const double ey = p.y[n] - (ay + u * ly3 + w * ry3);
      const double ez = p.z[n] - (az + u * lz3 + w * rz3);
      const double b = budget[n];
      if (ex * ex + ey * ey + ez * ez > b * b) return false;
    }
  }
  return true;
}

}  // namespace

bool within_budget(const GridHierarchy& grid, const NodePositions& p, const float* budget,
                   float largest, const Tri& t, long long* visited) {
  // Legs apex->left and apex->right are orthogonal and of equal length, so the barycentric
  // weights of left and right are plain projections onto them.
  const int lx = t.left.x - t.apex.x, ly = t.left.y - t.apex.y;
  const int rx = t.right.x - t.apex.x, ry = t.right.y - t.apex.y;
  const double inv_len2 = 1.0 / (double(lx) * lx + double(ly) * ly);
  const std::uint32_t a = grid.id(t.apex), l = grid.id(t.left), r = grid.id(t.right);
  // In float so that rows vectorize. Every component of the miss vector is then within about
  // 24 eps * largest of its exact value (weights err by a few eps and multiply differences of
  // at most 2 * largest; three sums of magnitude <= 3 * largest), so its length is within
  // 42 eps * largest. With 64 eps * largest of slack each way, a node is surely within or surely
  // over its budget; the rare triangle with a node in between is decided in double.
  const float slack = 64 * largest * std::numeric_limits<float>::epsilon();
  const float ax = p.x[a], ay = p.y[a], az = p.z[a];
  const float lx3 = p.x[l] - ax, ly3 = p.y[l] - ay, lz3 = p.z[l] - az;
  const float rx3 = p.x[r] - ax, ry3 = p.y[r] - ay, rz3 = p.z[r] - az;
  const int y0 = std::min({t.apex.y, t.left.y, t.right.y});
  const int y1 = std::max({t.apex.y, t.left.y, t.right.y});
  const std::size_t cols = static_cast<std::size_t>(grid.cols());
  long long count = 0;
  bool ok = true;
  bool undecided = false;
  const RowSpans spans(t);
  for (int y = y0; y <= y1 && ok; ++y) {
    int x0, x1;
    if (!spans.span(y, x0, x1)) continue;
    const int dy = y - t.apex.y;
    // Weights along the row are linear in x; the row is tested whole (no early exit inside, it
    // goes four nodes at a time) and the scan stops after the first row with a node over budget.
    const float u0 = static_cast<float>((double(x0 - t.apex.x) * lx + double(dy) * ly) * inv_len2);
    const float w0 = static_cast<float>((double(x0 - t.apex.x) * rx + double(dy) * ry) * inv_len2);
    const float du = static_cast<float>(lx * inv_len2), dw = static_cast<float>(rx * inv_len2);
    const std::size_t base = static_cast<std::size_t>(y) * cols + static_cast<std::size_t>(x0);
    const int len = x1 - x0 + 1;
    const RowVerdict v = scan_row(p.x + base, p.y + base, p.z + base, budget + base, len,
                                  {u0, w0, du, dw, ax, ay, az, lx3, ly3, lz3, rx3, ry3, rz3, slack});
    count += len;
    ok = !v.over;
    undecided |= v.close;
  }
  if (visited) *visited += count;
  if (ok && undecided) return within_budget_double(grid, p, budget, t);
  return ok;
}

bool fan_within_budget(const GridPolygon& poly, const NodePositions& p, const float* budget,
                       long long* visited) {
  const std::size_t cols = static_cast<std::size_t>(p.cols);
  const auto node = [&](Point q) { return static_cast<std::size_t>(q.y) * cols + static_cast<std::size_t>(q.x); };
  for (int k = 1; k + 1 < poly.count; ++k) {
    const Point a = poly.corner[0], b = poly.corner[k], c = poly.corner[k + 1];
    const long long det = static_cast<long long>(b.x - a.x) * (c.y - a.y) -
                          static_cast<long long>(b.y - a.y) * (c.x - a.x);
    if (det == 0) continue;
    const std::size_t na = node(a), nb = node(b), nc = node(c);
    for (int y = std::min({a.y, b.y, c.y}); y <= std::max({a.y, b.y, c.y}); ++y)
      for (int x = std::min({a.x, b.x, c.x}); x <= std::max({a.x, b.x, c.x}); ++x) {
        // Barycentric weights times det, exact in integers; inside when all have det's sign.
        const long long wb = static_cast<long long>(x - a.x) * (c.y - a.y) - static_cast<long long>(y - a.y) * (c.x - a.x);
        const long long wc = static_cast<long long>(b.x - a.x) * (y - a.y) - static_cast<long long>(b.y - a.y) * (x - a.x);
        const long long wa = det - wb - wc;
        if (det > 0 ? (wa < 0 || wb < 0 || wc < 0) : (wa > 0 || wb > 0 || wc > 0)) continue;
        if (visited) ++*visited;
        const double fa = double(wa) / double(det), fb = double(wb) / double(det), fc = double(wc) / double(det);
        const std::size_t n = node({x, y});
        const double ex = p.x[n] - (fa * p.x[na] + fb * p.x[nb] + fc * p.x[nc]);
        const double ey = p.y[n] - (fa * p.y[na] + fb * p.y[nb] + fc * p.y[nc]);
        const double ez = p.z[n] - (fa * p.z[na] + fb * p.z[nb] + fc * p.z[nc]);
        const double bud = budget[n];
        if (ex * ex + ey * ey + ez * ez > bud * bud) return false;
      }
  }
  return true;
}

}  // namespace pond::lod
