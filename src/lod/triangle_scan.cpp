#include "lod/triangle_scan.h"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <limits>
#include <vector>

#include <emmintrin.h>  // SSE2: the row scan, four nodes at a time

namespace pond::lod {
namespace {

// The columns where each row of the closed triangle meets it. Its edges run at 0, 45 or 90
// degrees, so on the rows it spans the triangle lies between at most two lines on the left and
// two on the right, x = at_row0 + slope * y with integer slopes (a flat edge only ends the rows):
// the first column is the largest of the left lines, the last the smallest of the right ones.
class RowSpans {
 public:
  explicit RowSpans(const Tri& t) {
    const Point v[3] = {t.apex, t.left, t.right};
    int left = 0, right = 0;
    for (int k = 0; k < 3; ++k) {
      const Point a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
      if (a.y == b.y) continue;
      const int slope = (b.x - a.x) / (b.y - a.y);
      const Line line{a.x - slope * a.y, slope};
      // The third corner lies right of a left edge. Every triangle has a line on each side.
      if (c.x > line.at(c.y)) left_[left++] = line;
      else right_[right++] = line;
    }
    if (left == 1) left_[1] = left_[0];
    if (right == 1) right_[1] = right_[0];
  }
  int first(int y) const { return std::max(left_[0].at(y), left_[1].at(y)); }
  int last(int y) const { return std::min(right_[0].at(y), right_[1].at(y)); }

 private:
  struct Line {
    int at_row0, slope;
    int at(int y) const { return at_row0 + slope * y; }
  };
  Line left_[2], right_[2];
};

// A triangle's rows relative to its apex, which depend on its legs only: the first column and
// length of each (RowSpans') and the weights of its first node, made once per shape. Triangles
// come in a few sizes in eight orientations, so a scan's row reads its set-up instead of working
// it out.
struct ShapeRow {
  int dy, dx0, len;
  float u0, w0;
};
constexpr int kTabledLevels = 13;  // legs up to 2^12 cells; larger ones find their rows

const std::vector<ShapeRow>* shape_rows(int lx, int ly, int rx, int ry) {
  const int size = std::max(std::abs(lx), std::abs(ly));
  if (size >= 1 << kTabledLevels || (size & (size - 1)) != 0) return nullptr;  // not a hierarchy's legs
  const auto sign = [](int v) { return v > 0 ? 2 : v < 0 ? 0 : 1; };
  const int level = std::countr_zero(static_cast<unsigned>(size));  // legs are (2^k, 0) or (2^k, 2^k) turned
  const std::size_t key = static_cast<std::size_t>(((level * 3 + sign(lx)) * 3 + sign(ly)) * 9 + sign(rx) * 3 + sign(ry));
  thread_local std::vector<std::vector<ShapeRow>> shapes(kTabledLevels * 81);
  std::vector<ShapeRow>& rows = shapes[key];
  if (rows.empty()) {
    const float inv_len2 = 1.0f / static_cast<float>(lx * lx + ly * ly);  // as within_budget's
    const Tri t{{0, 0}, {lx, ly}, {rx, ry}};
    const RowSpans spans(t);
    for (int y = std::min({0, ly, ry}); y <= std::max({0, ly, ry}); ++y) {
      const int x0 = spans.first(y);
      rows.push_back({y, x0, spans.last(y) - x0 + 1, static_cast<float>(x0 * lx + y * ly) * inv_len2,
                      static_cast<float>(x0 * rx + y * ry) * inv_len2});
    }
  }
  return &rows;
}

// A triangle's interpolation for the row scan: the apex and the legs in world space (per axis), and
// as SSE2 vectors built once per triangle, how much the interpolation moves per column and the
// budgets' rounding slack. Along a row it is linear, so a row needs its first node's value only.
struct ScanPlane {
  float a[3], l[3], r[3];
  __m128 step[3];
  __m128 slack;
};

struct RowVerdict {
  bool over;   // a node is over its budget for sure
  bool close;  // a node is so near its budget that float cannot tell
};

// The squared misses of a row's nodes k .. k+3 (kf: those k as floats) from the interpolation,
// which is `first` at the row's first node and moves by a step per column.
inline __m128 squared_miss(const float* px, const float* py, const float* pz, int k, __m128 kf, const __m128 first[3],
                           const ScanPlane& r) {
  const __m128 ex = _mm_sub_ps(_mm_loadu_ps(px + k), _mm_add_ps(first[0], _mm_mul_ps(kf, r.step[0])));
  const __m128 ey = _mm_sub_ps(_mm_loadu_ps(py + k), _mm_add_ps(first[1], _mm_mul_ps(kf, r.step[1])));
  const __m128 ez = _mm_sub_ps(_mm_loadu_ps(pz + k), _mm_add_ps(first[2], _mm_mul_ps(kf, r.step[2])));
  return _mm_add_ps(_mm_add_ps(_mm_mul_ps(ex, ex), _mm_mul_ps(ey, ey)), _mm_mul_ps(ez, ez));
}

// The nodes k = 0 .. len-1 of a row, four at a time. The last group's lanes past the row read the
// following nodes (or the arrays' padding) and are masked out, so there is no scalar tail.
// First, one compare a node: is any miss over its sure-within threshold (scan_thresholds())? Only
// a row where one is gets the exact test, which tells a node surely over from one too close to call.
RowVerdict scan_row(const float* px, const float* py, const float* pz, const ScanBudgets& budgets, int len,
                    const __m128 first[3], const ScanPlane& r) {
  const __m128 zero = _mm_setzero_ps(), four = _mm_set1_ps(4), end = _mm_set1_ps(static_cast<float>(len));
  const __m128 lanes = _mm_setr_ps(0, 1, 2, 3);  // exact integers
  __m128 maybe = zero, kf = lanes;
  for (int k = 0; k < len; k += 4, kf = _mm_add_ps(kf, four)) {
    const __m128 e2 = _mm_and_ps(_mm_cmplt_ps(kf, end), squared_miss(px, py, pz, k, kf, first, r));  // 0 past the row
    maybe = _mm_or_ps(maybe, _mm_cmpgt_ps(e2, _mm_loadu_ps(budgets.sure2 + k)));
  }
  if (_mm_movemask_ps(maybe) == 0) return {false, false};
  const __m128 grow = _mm_set1_ps(1 + 1e-6f);
  __m128 over = zero, close = zero;
  kf = lanes;
  for (int k = 0; k < len; k += 4, kf = _mm_add_ps(kf, four)) {
    const __m128 live = _mm_cmplt_ps(kf, end);
    const __m128 e2 = squared_miss(px, py, pz, k, kf, first, r);
    const __m128 high = _mm_add_ps(_mm_loadu_ps(budgets.budget + k), r.slack);
    over = _mm_or_ps(over, _mm_and_ps(live, _mm_cmpgt_ps(e2, _mm_mul_ps(_mm_mul_ps(high, high), grow))));
    close = _mm_or_ps(close, _mm_and_ps(live, _mm_cmpgt_ps(e2, _mm_loadu_ps(budgets.sure2 + k))));
  }
  return {_mm_movemask_ps(over) != 0, _mm_movemask_ps(close) != 0};
}

// The float scan's rounding slack on a budget, for |coordinates| up to `largest` (see the analysis
// in within_budget()).
float scan_slack(float largest) { return 64 * largest * std::numeric_limits<float>::epsilon(); }

}  // namespace

namespace {

// The same test in double, for triangles the float pass cannot decide: every node is then
// judged within 1e-13 relative, far inside the budgets' own 1e-5 margin.
bool within_budget_double(const GridHierarchy& grid, const NodePositions& p, const float* budget,
                          const Tri& t, const TriCorners& c, const Tri& region) {
  const int lx = t.left.x - t.apex.x, ly = t.left.y - t.apex.y;
  const int rx = t.right.x - t.apex.x, ry = t.right.y - t.apex.y;
  const double inv_len2 = 1.0 / (double(lx) * lx + double(ly) * ly);
  const double ax = c.x[0], ay = c.y[0], az = c.z[0];
  const double lx3 = c.x[1] - ax, ly3 = c.y[1] - ay, lz3 = c.z[1] - az;
  const double rx3 = c.x[2] - ax, ry3 = c.y[2] - ay, rz3 = c.z[2] - az;
  const int y0 = std::min({region.apex.y, region.left.y, region.right.y});
  const int y1 = std::max({region.apex.y, region.left.y, region.right.y});
  const std::size_t cols = static_cast<std::size_t>(grid.cols());
  const RowSpans spans(region);
  for (int y = y0; y <= y1; ++y) {
    const int dy = y - t.apex.y;
    for (int x = spans.first(y), x1 = spans.last(y); x <= x1; ++x) {
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

void scan_thresholds(const float* budget, std::size_t n, float largest, float* sure2) {
  const __m128 slack = _mm_set1_ps(scan_slack(largest)), shrink = _mm_set1_ps(1 - 1e-6f), zero = _mm_setzero_ps();
  for (std::size_t k = 0; k < n; k += 4) {  // the last group's lanes past n into the padding
    const __m128 low = _mm_max_ps(_mm_sub_ps(_mm_loadu_ps(budget + k), slack), zero);
    _mm_storeu_ps(sure2 + k, _mm_mul_ps(_mm_mul_ps(low, low), shrink));
  }
}

bool within_budget(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets,
                   float largest, const Tri& t, long long* visited) {
  return within_budget(grid, p, budgets, largest, t, t, visited);
}

bool within_budget(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets,
                   float largest, const Tri& t, const Tri& region, long long* visited) {
  TriCorners c;
  const Point corner[3] = {t.apex, t.left, t.right};
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t n = grid.id(corner[k]);
    c.x[k] = p.x[n], c.y[k] = p.y[n], c.z[k] = p.z[n];
  }
  return within_budget(grid, p, budgets, largest, t, c, region, visited);
}

bool within_budget(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets,
                   float largest, const Tri& t, const TriCorners& c, const Tri& region, long long* visited) {
  // Legs apex->left and apex->right are orthogonal and of equal length, so the barycentric
  // weights of left and right are plain projections onto them. The squared leg length is a
  // power of two (legs are (2^k, 0) or (2^k, 2^k) turned), so every weight, the integer
  // projection times its inverse, is exact in float.
  const int lx = t.left.x - t.apex.x, ly = t.left.y - t.apex.y;
  const int rx = t.right.x - t.apex.x, ry = t.right.y - t.apex.y;
  const float inv_len2 = 1.0f / static_cast<float>(static_cast<long long>(lx) * lx + static_cast<long long>(ly) * ly);
  // In float so that rows vectorize. With M = `largest`, each component of the miss vector is
  // within 16 eps * M of its exact value: the legs (differences of coordinates <= M) err by eps * M;
  // a row's first value a + u0 l + w0 r (weights in [0, 1]) by 6 eps * M; the step du l + dw r,
  // times k, by 6 eps * M (k du and k dw are differences of two nodes' weights, <= 1 each); the
  // product, the sum and the difference by 3.5 eps * M. So the length is within 28 eps * M, and
  // with 64 eps * M of slack each way a node is surely within or surely over its budget; the rare
  // triangle with a node in between is decided in double.
  const float slack = scan_slack(largest);
  const float du = static_cast<float>(lx) * inv_len2, dw = static_cast<float>(rx) * inv_len2;
  ScanPlane plane;
  for (int i = 0; i < 3; ++i) {
    const float* v = i == 0 ? c.x : i == 1 ? c.y : c.z;
    plane.a[i] = v[0], plane.l[i] = v[1] - v[0], plane.r[i] = v[2] - v[0];
    plane.step[i] = _mm_set1_ps(du * plane.l[i] + dw * plane.r[i]);
  }
  plane.slack = _mm_set1_ps(slack);
  const int y0 = std::min({region.apex.y, region.left.y, region.right.y});
  const int y1 = std::max({region.apex.y, region.left.y, region.right.y});
  const std::size_t cols = static_cast<std::size_t>(grid.cols());
  long long count = 0;
  bool ok = true;
  bool undecided = false;
  // The region's rows from the table of its shape (with their weights where it is t itself).
  const bool whole = region.apex == t.apex && region.left == t.left && region.right == t.right;
  const std::vector<ShapeRow>* tabled =
      shape_rows(region.left.x - region.apex.x, region.left.y - region.apex.y, region.right.x - region.apex.x,
                 region.right.y - region.apex.y);
  // Each row is tested whole (no early exit inside, it goes four nodes at a time) and the scan
  // stops after the first row with a node over budget.
  const auto row = [&](std::ptrdiff_t base, int len, float u0, float w0) {
    const __m128 first[3] = {_mm_set1_ps(plane.a[0] + u0 * plane.l[0] + w0 * plane.r[0]),
                             _mm_set1_ps(plane.a[1] + u0 * plane.l[1] + w0 * plane.r[1]),
                             _mm_set1_ps(plane.a[2] + u0 * plane.l[2] + w0 * plane.r[2])};
    const RowVerdict v = scan_row(p.x + base, p.y + base, p.z + base, {budgets.budget + base, budgets.sure2 + base}, len,
                                  first, plane);
    count += len;
    ok = !v.over;
    undecided |= v.close;
  };
  const std::ptrdiff_t pitch = static_cast<std::ptrdiff_t>(cols);
  if (tabled) {
    const std::ptrdiff_t apex = region.apex.y * pitch + region.apex.x;
    const long long ox = region.apex.x - t.apex.x, oy = region.apex.y - t.apex.y;  // region's apex from t's
    if (whole) {
      for (auto r = tabled->begin(); r != tabled->end() && ok; ++r) row(apex + r->dy * pitch + r->dx0, r->len, r->u0, r->w0);
    } else {  // a part: t's weights of each row's first node
      for (auto r = tabled->begin(); r != tabled->end() && ok; ++r) {
        const long long dx = ox + r->dx0, dy = oy + r->dy;
        row(apex + r->dy * pitch + r->dx0, r->len, static_cast<float>(dx * lx + dy * ly) * inv_len2,
            static_cast<float>(dx * rx + dy * ry) * inv_len2);
      }
    }
  } else {
    const RowSpans spans(region);
    for (int y = y0; y <= y1 && ok; ++y) {
      // Weights along the row are linear in x.
      const int x0 = spans.first(y);
      const long long dx = x0 - t.apex.x, dy = y - t.apex.y;
      row(y * pitch + x0, spans.last(y) - x0 + 1, static_cast<float>(dx * lx + dy * ly) * inv_len2,
          static_cast<float>(dx * rx + dy * ry) * inv_len2);
    }
  }
  if (visited) *visited += count;
  if (ok && undecided) return within_budget_double(grid, p, budgets.budget, t, c, region);
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
