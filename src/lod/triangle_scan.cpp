#include "lod/triangle_scan.h"

#include <algorithm>
#include <climits>
#include <limits>

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
  int undecided = 0;
  const RowSpans spans(t);
  for (int y = y0; y <= y1 && ok; ++y) {
    int x0, x1;
    if (!spans.span(y, x0, x1)) continue;
    const int dy = y - t.apex.y;
    // Weights along the row are linear in x; the row is tested whole (no early exit inside, so
    // the loop vectorizes) and the scan stops after the first row with a node over budget.
    const float u0 = static_cast<float>((double(x0 - t.apex.x) * lx + double(dy) * ly) * inv_len2);
    const float w0 = static_cast<float>((double(x0 - t.apex.x) * rx + double(dy) * ry) * inv_len2);
    const float du = static_cast<float>(lx * inv_len2), dw = static_cast<float>(rx * inv_len2);
    const std::size_t base = static_cast<std::size_t>(y) * cols + static_cast<std::size_t>(x0);
    const float* px = p.x + base;
    const float* py = p.y + base;
    const float* pz = p.z + base;
    const float* pb = budget + base;
    const int len = x1 - x0 + 1;
    int over = 0, close = 0;
    for (int k = 0; k < len; ++k) {
      const float kf = static_cast<float>(k);
      const float u = u0 + kf * du, w = w0 + kf * dw;
      const float ex = px[k] - (ax + u * lx3 + w * rx3);
      const float ey = py[k] - (ay + u * ly3 + w * ry3);
      const float ez = pz[k] - (az + u * lz3 + w * rz3);
      const float e2 = ex * ex + ey * ey + ez * ez;
      const float high = pb[k] + slack, low = std::max(pb[k] - slack, 0.0f);
      over |= e2 > high * high * (1 + 1e-6f);    // over budget for sure
      close |= e2 > low * low * (1 - 1e-6f);     // maybe over: float cannot tell
    }
    count += len;
    ok = over == 0;
    undecided |= close;
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
