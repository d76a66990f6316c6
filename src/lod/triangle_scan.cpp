#include "lod/triangle_scan.h"

#include <algorithm>
#include <vector>

#include "lod/scan_rows.h"
#include "sim/wide_baseline.h"

namespace pond::lod {

using sim::WideBaseline;  // the scans' table where the AVX2 copy does not run (SSE2, NEON)

const ShapeTable* make_shape_table(ShapeTable& table, int lx, int ly, int rx, int ry, std::ptrdiff_t pitch) {
  const float inv_len2 = inverse_square_leg(lx, ly);  // as scan_by_rows's
  const Tri t{{0, 0}, {lx, ly}, {rx, ry}};
  const RowSpans spans(t);
  std::size_t nodes = 0;
  for (int y = std::min({0, ly, ry}); y <= std::max({0, ly, ry}); ++y) {
    const int x0 = spans.first(y), len = spans.last(y) - x0 + 1;
    table.rows.push_back({y * pitch + x0, y, x0, len, static_cast<float>(x0 * lx + y * ly) * inv_len2,
                          static_cast<float>(x0 * rx + y * ry) * inv_len2});
    nodes += static_cast<std::size_t>(len);
  }
  // Rows shorter than a group on average: pieces of up to four nodes, two a group, each node's
  // weights exact as a row's first node's are. The corners are left out: the interpolation meets
  // them exactly (in double, a + (c - a) is c), so with budgets >= 0 no corner fails a triangle.
  if (nodes < 8 * table.rows.size()) {
    table.grouped = true;
    const auto corner = [&](int x, int y) { return (x == 0 && y == 0) || (x == lx && y == ly) || (x == rx && y == ry); };
    int lane = 0;
    std::int32_t seen = 0;
    for (const ShapeRow& r : table.rows) {
      int x0 = r.dx0, x1 = r.dx0 + r.len - 1;  // the row's nodes but its corners
      if (corner(x0, r.dy)) ++x0;
      if (x1 >= x0 && corner(x1, r.dy)) --x1;
      for (int x = x0; x <= x1; x += 4) {
        if (lane == 0) table.groups.push_back({});
        ShapeGroup& g = table.groups.back();
        g.offset[lane / 4] = static_cast<std::int32_t>(r.dy * pitch + x);
        for (int k = 0; k < 4; ++k) {
          g.u[lane + k] = static_cast<float>((x + k) * lx + r.dy * ly) * inv_len2;
          g.w[lane + k] = static_cast<float>((x + k) * rx + r.dy * ry) * inv_len2;
          g.live[lane + k] = x + k <= x1 ? ~0u : 0u;
        }
        seen += std::min(4, x1 - x + 1);
        g.through = seen;
        lane = (lane + 4) % 8;
      }
    }
    if (lane == 4) table.groups.back().offset[1] = table.groups.back().offset[0];  // its live lanes are all 0
    table.grouped_nodes = static_cast<std::size_t>(seen);
  }
  return &table;
}

bool row_within_budget_double(const GridHierarchy& grid, const NodePositions& p, const float* budget, const Tri& t,
                              const TriCorners& c, int y, int x0, int x1) {
  const int lx = t.left.x - t.apex.x, ly = t.left.y - t.apex.y;
  const int rx = t.right.x - t.apex.x, ry = t.right.y - t.apex.y;
  const double inv_len2 = 1.0 / (double(lx) * lx + double(ly) * ly);
  const double ax = c.x[0], ay = c.y[0], az = c.z[0];
  const double lx3 = c.x[1] - ax, ly3 = c.y[1] - ay, lz3 = c.z[1] - az;
  const double rx3 = c.x[2] - ax, ry3 = c.y[2] - ay, rz3 = c.z[2] - az;
  const std::size_t cols = static_cast<std::size_t>(grid.cols());
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
  return true;
}

void scan_thresholds(const float* budget, std::size_t n, float largest, float* sure2, [[maybe_unused]] bool wide) {
#if POND_LOD_AVX2
  if (wide) return scan_thresholds_avx2(budget, n, largest, sure2);
#endif
  scan_thresholds_with<WideBaseline>(budget, n, largest, sure2);
}

namespace {

// The scans, out of line like the AVX2 copy: each within_budget() below then only chooses and
// jumps, with no registers of its own to save. `c`: t's corners, or nullptr where `p` holds them
// (read there only where needed).
[[gnu::noinline]] bool scan_triangle_baseline(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets,
                                          float largest, const Tri& t, const TriCorners* c, const Tri& region,
                                          long long* visited) {
  return scan_triangle<WideBaseline>(grid, p, budgets, largest, t, c, region, visited);
}

inline bool scan(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets, float largest,
                 const Tri& t, const TriCorners* c, const Tri& region, long long* visited) {
#if POND_LOD_AVX2
  if (budgets.wide) return scan_triangle_avx2(grid, p, budgets, largest, t, c, region, visited);
#endif
  return scan_triangle_baseline(grid, p, budgets, largest, t, c, region, visited);
}

}  // namespace

bool within_budget(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets,
                   float largest, const Tri& t, long long* visited) {
  return scan(grid, p, budgets, largest, t, nullptr, t, visited);
}

bool within_budget(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets,
                   float largest, const Tri& t, const Tri& region, long long* visited) {
  return scan(grid, p, budgets, largest, t, nullptr, region, visited);
}

bool within_budget(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets,
                   float largest, const Tri& t, const TriCorners& c, const Tri& region, long long* visited) {
  return scan(grid, p, budgets, largest, t, &c, region, visited);
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
