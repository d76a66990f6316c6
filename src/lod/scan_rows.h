#pragma once
// The exact scan's float pass (triangle_scan.h), written once against the wide-float tables
// (sim/wide_*.h) and built like the node budgets (budget_loop.h): by triangle_scan.cpp with the
// target's baseline table (SSE2 or NEON, four nodes a group), and on x86-64 by
// triangle_scan_avx2.cpp with AVX2's, eight; the eight-lane copy scans a whole small triangle in
// groups of row pieces instead (group_scan, with AVX2's load_halves). Every path decides in float
// only the nodes float rounding cannot mislead (inside the slack of scan_by_rows()'s analysis) and
// the others by the same test in double, so all give the same verdicts. The code of each copy is in
// its file's inline namespace (sim/isa_namespace.h), not the linker's pick.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "lod/grid_hierarchy.h"
#include "lod/node_positions.h"
#include "lod/triangle_scan.h"
#include "sim/isa_namespace.h"

namespace pond::lod {
inline namespace POND_ISA {

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

}  // namespace POND_ISA

// A triangle's rows relative to its apex, which depend on its legs only: the first column and
// length of each (RowSpans'), its first node's offset in arrays of a given pitch and its weights,
// made once per shape and pitch. Triangles come in a few sizes in eight orientations, so a scan's
// row reads its set-up instead of working it out.
struct ShapeRow {
  std::ptrdiff_t offset;  // dy * pitch + dx0
  int dy, dx0, len;
  float u0, w0;
};
// The same triangle in groups of eight nodes for the AVX2 scan of a shape whose rows are short:
// each row cut into pieces of up to four nodes, two pieces a group (each one 16-byte load), with
// every lane's exact weights and whether it is a node of the triangle (a piece shorter than four
// reads nodes beyond it, masked out).
struct ShapeGroup {
  std::int32_t offset[2];  // the pieces' first nodes from the apex (lanes 0-3, 4-7)
  float u[8], w[8];
  std::uint32_t live[8];   // all ones for a node of the triangle, else 0
  std::int32_t through;    // the nodes in this group and those before it
};
struct ShapeTable {
  std::vector<ShapeRow> rows;
  bool grouped = false;            // whether the groups are made (else the rows are scanned)
  std::vector<ShapeGroup> groups;  // the nodes but the corners
  std::size_t grouped_nodes = 0;
};
constexpr int kTabledLevels = 13;  // legs up to 2^12 cells; larger ones find their rows
// Fills `table`, the triangle with legs (lx, ly) and (rx, ry) from its apex in arrays of `pitch`
// floats a row, and returns it (triangle_scan.cpp). Out of line: the lookup below stays small.
const ShapeTable* make_shape_table(ShapeTable& table, int lx, int ly, int rx, int ry, std::ptrdiff_t pitch);

// The scan in double of row y's columns x0 .. x1 against t's interpolation, for a row the float
// pass cannot decide (triangle_scan.cpp). Every node is judged within 1e-13 relative, far inside
// the budgets' own 1e-5 margin.
bool row_within_budget_double(const GridHierarchy& grid, const NodePositions& p, const float* budget, const Tri& t,
                              const TriCorners& c, int y, int x0, int x1);

#if POND_LOD_AVX2
// scan_triangle's and scan_thresholds' AVX2 copies (triangle_scan_avx2.cpp): the same operations
// lane for lane, so the same bits. (Declared here, defined there: outside the inline namespace.)
bool scan_triangle_avx2(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets, float largest,
                        const Tri& t, const TriCorners* c, const Tri& region, long long* visited);
void scan_thresholds_avx2(const float* budget, std::size_t n, float largest, float* sure2);
#endif

inline namespace POND_ISA {

// The rows of the triangle with legs (lx, ly) and (rx, ry) in arrays of `pitch` floats a row, or
// nullptr for legs the tables do not hold. Each thread, and each copy of the scan, keeps the
// tables of its last four pitches: a frame's blocks have one or two (the grid's last blocks may be
// narrower), the whole grid its own, and a view may switch between the two from frame to frame.
struct ShapeTables {
  std::ptrdiff_t pitch = -1;
  std::vector<ShapeTable> shapes;
};
constexpr int kPitches = 4;
// Internal to each file that includes this (each copy of the scan has its own, in its own ISA
// namespace): an inline variable's thread_local is reached through a TLS wrapper call on every
// lookup, in the scan's hot path.
static thread_local ShapeTables shape_tables[kPitches];

// shape_table()'s other cases: `pitch` not the most recent one, or the shape not yet tabled.
// Out of line, so the common lookup stays a few instructions inlined into the scan.
[[gnu::noinline]] inline const ShapeTable* shape_table_miss(std::size_t key, int lx, int ly, int rx, int ry,
                                                            std::ptrdiff_t pitch) {
  ShapeTables* tables = shape_tables;
  if (tables[0].pitch != pitch) {  // the most recent first
    int i = 1;
    while (i < kPitches && tables[i].pitch != pitch) ++i;
    if (i == kPitches) tables[--i] = {pitch, std::vector<ShapeTable>(kTabledLevels * 81)};
    std::rotate(tables, tables + i, tables + i + 1);
  }
  ShapeTable& table = tables[0].shapes[key];
  return table.rows.empty() ? make_shape_table(table, lx, ly, rx, ry, pitch) : &table;
}

inline const ShapeTable* shape_table(int lx, int ly, int rx, int ry, std::ptrdiff_t pitch) {
  const unsigned size = static_cast<unsigned>(std::max(std::abs(lx), std::abs(ly)));
  if (size == 0 || size >= 1u << kTabledLevels || (size & (size - 1)) != 0) return nullptr;  // not a hierarchy's legs
  // Legs are (2^k, 0) or (2^k, 2^k) turned, so each component shifted right by k is its sign.
  const int level = std::countr_zero(size);
  const auto sign = [level](int v) { return (v >> level) + 1; };
  const std::size_t key = static_cast<std::size_t>(((level * 3 + sign(lx)) * 3 + sign(ly)) * 9 + sign(rx) * 3 + sign(ry));
  const ShapeTables& recent = shape_tables[0];
  if (recent.pitch == pitch && !recent.shapes[key].rows.empty()) return &recent.shapes[key];
  return shape_table_miss(key, lx, ly, rx, ry, pitch);
}

// A triangle's interpolation for the row scan, as vectors built once per triangle: how much it
// moves per column, and the budgets' rounding slack. Along a row it is linear, so a row needs its
// first node's value only.
template <class W>
struct ScanPlane {
  typename W::F step[3];
  typename W::F slack;
};

struct RowVerdict {
  bool over;   // a node is over its budget for sure
  bool close;  // a node is so near its budget that float cannot tell
};

// The squared misses of a row's nodes k .. k + W::width - 1 (kf: those k as floats) from the
// interpolation, which is `first` at the row's first node and moves by a step per column.
template <class W>
inline typename W::F squared_miss(const float* px, const float* py, const float* pz, int k, typename W::F kf,
                                  const typename W::F first[3], const ScanPlane<W>& r) {
  using F = typename W::F;
  const F ex = W::sub(W::load(px + k), W::add(first[0], W::mul(kf, r.step[0])));
  const F ey = W::sub(W::load(py + k), W::add(first[1], W::mul(kf, r.step[1])));
  const F ez = W::sub(W::load(pz + k), W::add(first[2], W::mul(kf, r.step[2])));
  return W::add(W::add(W::mul(ex, ex), W::mul(ey, ey)), W::mul(ez, ez));
}

// The nodes k = 0 .. len-1 of a row, W::width at a time. The last group's lanes past the row read
// the following nodes (or the arrays' padding) and are masked out, so there is no scalar tail.
// First, one compare a node: is any miss over its sure-within threshold (scan_thresholds())? Only
// a row where one is gets the exact test, which tells a node surely over from one too close to call.
template <class W>
RowVerdict scan_row(const float* px, const float* py, const float* pz, const ScanBudgets& budgets, int len,
                    const typename W::F first[3], const ScanPlane<W>& r) {
  using F = typename W::F;
  using M = typename W::M;
  const F width = W::set1(W::width), end = W::set1(static_cast<float>(len));
  F kf = W::iota();  // exact integers
  M maybe = W::none();
  for (int k = 0; k < len; k += W::width, kf = W::add(kf, width)) {
    const F e2 = W::keep(W::less(kf, end), squared_miss<W>(px, py, pz, k, kf, first, r));  // 0 past the row
    maybe = W::either(maybe, W::greater(e2, W::load(budgets.sure2 + k)));
  }
  if (!W::any(maybe)) return {false, false};
  const F grow = W::set1(1 + 1e-6f);
  M over = W::none(), close = over;
  kf = W::iota();
  for (int k = 0; k < len; k += W::width, kf = W::add(kf, width)) {
    const M live = W::less(kf, end);
    const F e2 = squared_miss<W>(px, py, pz, k, kf, first, r);
    const F high = W::add(W::load(budgets.budget + k), r.slack);
    over = W::either(over, W::both(live, W::greater(e2, W::mul(W::mul(high, high), grow))));
    close = W::either(close, W::both(live, W::greater(e2, W::load(budgets.sure2 + k))));
  }
  return {W::any(over), W::any(close)};
}

// The float scan's rounding slack on a budget, for |coordinates| up to `largest` (see the analysis
// in scan_by_rows()).
inline float scan_slack(float largest) { return 64 * largest * std::numeric_limits<float>::epsilon(); }

// A triangle's interpolation in world space, from its corners: the apex and the legs, x, y, z each.
struct WorldLegs {
  float a[3], l[3], r[3];
};
// t's corners' world positions, where `p` holds them.
inline TriCorners corners_of(const GridHierarchy& grid, const NodePositions& p, const Tri& t) {
  TriCorners c;
  const Point corner[3] = {t.apex, t.left, t.right};
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t n = grid.id(corner[k]);
    c.x[k] = p.x[n], c.y[k] = p.y[n], c.z[k] = p.z[n];
  }
  return c;
}
// world_legs(corners_of(grid, p, t)) without the copy (which GCC keeps): the same values, read
// from `p`.
inline WorldLegs world_legs(const GridHierarchy& grid, const NodePositions& p, const Tri& t) {
  const std::uint32_t a = grid.id(t.apex), l = grid.id(t.left), r = grid.id(t.right);
  WorldLegs w;
  const float* const axes[3] = {p.x, p.y, p.z};
  for (int i = 0; i < 3; ++i) {
    const float* v = axes[i];
    w.a[i] = v[a], w.l[i] = v[l] - v[a], w.r[i] = v[r] - v[a];
  }
  return w;
}
inline WorldLegs world_legs(const TriCorners& c) {
  WorldLegs w;
  for (int i = 0; i < 3; ++i) {
    const float* v = i == 0 ? c.x : i == 1 ? c.y : c.z;
    w.a[i] = v[0], w.l[i] = v[1] - v[0], w.r[i] = v[2] - v[0];
  }
  return w;
}

// The scan of a whole triangle of `table`'s shape with its apex at node `apex`, a group of two
// row pieces at a time: each node's interpolation a + u l + w r from its own (exact) weights,
// rounded as a row's first value is (so within scan_by_rows()'s analysis); the nodes float cannot
// decide are judged in double. Counts the nodes visited into *count.
template <class W>
bool group_scan(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets, const Tri& t,
                const TriCorners* c, const ShapeTable& table, std::ptrdiff_t apex, const WorldLegs& legs, float slack,
                long long* count) {
  using F = typename W::F;
  static_assert(W::width == 8);
  const float *px = p.x + apex, *py = p.y + apex, *pz = p.z + apex, *sure2 = budgets.sure2 + apex;
  const ShapeGroup* g = table.groups.data();
  const ShapeGroup* const end = g + table.groups.size();
  while (g != end) {
    // The groups up to the next one with a node float cannot call within, with the interpolation's
    // terms in registers: no call in this loop, so none of them is saved around one.
    const F ax = W::set1(legs.a[0]), ay = W::set1(legs.a[1]), az = W::set1(legs.a[2]);
    const F lx = W::set1(legs.l[0]), ly = W::set1(legs.l[1]), lz = W::set1(legs.l[2]);
    const F rx = W::set1(legs.r[0]), ry = W::set1(legs.r[1]), rz = W::set1(legs.r[2]);
    F e2 = W::set1(0);
    typename W::M close = W::none();
    for (; g != end; ++g) {
      const std::int32_t lo = g->offset[0], hi = g->offset[1];
      const F u = W::load(g->u), w = W::load(g->w);
      const F ex = W::sub(W::load_halves(px + lo, px + hi), W::add(W::add(ax, W::mul(u, lx)), W::mul(w, rx)));
      const F ey = W::sub(W::load_halves(py + lo, py + hi), W::add(W::add(ay, W::mul(u, ly)), W::mul(w, ry)));
      const F ez = W::sub(W::load_halves(pz + lo, pz + hi), W::add(W::add(az, W::mul(u, lz)), W::mul(w, rz)));
      e2 = W::keep(W::load_mask(g->live), W::add(W::add(W::mul(ex, ex), W::mul(ey, ey)), W::mul(ez, ez)));  // 0 off the triangle
      close = W::greater(e2, W::load_halves(sure2 + lo, sure2 + hi));
      if (W::any(close)) break;
    }
    if (g == end) break;
    // Group g has a node near its budget: over for sure, or decided in double.
    const std::int32_t lo = g->offset[0], hi = g->offset[1];
    const auto fail = [&] {
      *count += g->through;
      return false;
    };
    const float* budget = budgets.budget + apex;
    const F high = W::add(W::load_halves(budget + lo, budget + hi), W::set1(slack));
    if (W::any(W::greater(e2, W::mul(W::mul(high, high), W::set1(1 + 1e-6f))))) return fail();
    const std::ptrdiff_t pitch = static_cast<std::ptrdiff_t>(grid.cols());
    const TriCorners corners = c ? *c : corners_of(grid, p, t);
    const unsigned closes = W::lanes_set(close);
    for (int k = 0; k < W::width; ++k) {
      if ((closes >> k & 1) == 0) continue;
      const std::ptrdiff_t node = apex + (k < 4 ? lo + k : hi + k - 4);
      const int y = static_cast<int>(node / pitch), x = static_cast<int>(node % pitch);
      if (!row_within_budget_double(grid, p, budgets.budget, t, corners, y, x, x)) return fail();
    }
    ++g;
  }
  *count += static_cast<long long>(table.grouped_nodes);
  return true;
}

// 1 / (lx^2 + ly^2) for a hierarchy's leg (lx, ly), exactly: the squared length is a power of two,
// so its inverse is that float's exponent negated (legs up to 2^62 cells).
inline float inverse_square_leg(int lx, int ly) {
  const unsigned long long len2 = static_cast<unsigned long long>(static_cast<long long>(lx) * lx + static_cast<long long>(ly) * ly);
  return std::bit_cast<float>(static_cast<std::uint32_t>(127 - std::countr_zero(len2)) << 23);
}

// The float scan of `region`'s nodes against t's interpolation, row by row; `tabled` is the table of
// region's shape, or nullptr, and `whole` says region is t. Out of line: scan_triangle() stays
// small for its common case.
template <class W>
[[gnu::noinline]] bool scan_by_rows(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets,
                                    float largest, const Tri& t, const TriCorners& c, const Tri& region,
                                    const ShapeTable* tabled, bool whole, long long* visited) {
  // Legs apex->left and apex->right are orthogonal and of equal length, so the barycentric
  // weights of left and right are plain projections onto them. The squared leg length is a
  // power of two (legs are (2^k, 0) or (2^k, 2^k) turned), so every weight, the integer
  // projection times its inverse, is exact in float.
  const int lx = t.left.x - t.apex.x, ly = t.left.y - t.apex.y;
  const int rx = t.right.x - t.apex.x, ry = t.right.y - t.apex.y;
  const float inv_len2 = inverse_square_leg(lx, ly);
  // In float so that rows vectorize. With M = `largest`, each component of the miss vector is
  // within 16 eps * M of its exact value: the legs (differences of coordinates <= M) err by eps * M;
  // a row's first value a + u0 l + w0 r (weights in [0, 1]) by 6 eps * M; the step du l + dw r,
  // times k, by 6 eps * M (k du and k dw are differences of two nodes' weights, <= 1 each); the
  // product, the sum and the difference by 3.5 eps * M. So the length is within 28 eps * M, and
  // with 64 eps * M of slack each way a node is surely within or surely over its budget; the rare
  // row with a node in between is decided in double.
  const float slack = scan_slack(largest);
  const WorldLegs legs = world_legs(c);
  const std::ptrdiff_t pitch = static_cast<std::ptrdiff_t>(grid.cols());
  long long count = 0;
  const float du = static_cast<float>(lx) * inv_len2, dw = static_cast<float>(rx) * inv_len2;
  ScanPlane<W> plane;
  for (int i = 0; i < 3; ++i) plane.step[i] = W::set1(du * legs.l[i] + dw * legs.r[i]);
  plane.slack = W::set1(slack);
  bool ok = true;
  // Each row is tested whole (no early exit inside, it goes W::width nodes at a time), a row float
  // cannot decide once more in double, and the scan stops after the first row with a node over.
  const auto row = [&](std::ptrdiff_t base, int len, float u0, float w0) {
    // The row's first value (a + u0 l) + w0 r, in every lane.
    typename W::F first[3];
    for (int i = 0; i < 3; ++i) first[i] = W::set1((legs.a[i] + u0 * legs.l[i]) + w0 * legs.r[i]);
    const RowVerdict v = scan_row<W>(p.x + base, p.y + base, p.z + base,
                                     {budgets.budget + base, budgets.sure2 + base, budgets.wide}, len, first, plane);
    count += len;
    ok = !v.over && (!v.close || row_within_budget_double(grid, p, budgets.budget, t, c, static_cast<int>(base / pitch),
                                                          static_cast<int>(base % pitch),
                                                          static_cast<int>(base % pitch) + len - 1));
  };
  if (tabled) {
    const std::ptrdiff_t apex = region.apex.y * pitch + region.apex.x;
    const long long ox = region.apex.x - t.apex.x, oy = region.apex.y - t.apex.y;  // region's apex from t's
    if (whole) {
      for (auto r = tabled->rows.begin(); r != tabled->rows.end() && ok; ++r) row(apex + r->offset, r->len, r->u0, r->w0);
    } else {  // a part: t's weights of each row's first node
      for (auto r = tabled->rows.begin(); r != tabled->rows.end() && ok; ++r) {
        const long long dx = ox + r->dx0, dy = oy + r->dy;
        row(apex + r->offset, r->len, static_cast<float>(dx * lx + dy * ly) * inv_len2,
            static_cast<float>(dx * rx + dy * ry) * inv_len2);
      }
    }
  } else {
    const RowSpans spans(region);
    const int y1 = std::max({region.apex.y, region.left.y, region.right.y});
    for (int y = std::min({region.apex.y, region.left.y, region.right.y}); y <= y1 && ok; ++y) {
      // Weights along the row are linear in x.
      const int x0 = spans.first(y);
      const long long dx = x0 - t.apex.x, dy = y - t.apex.y;
      row(y * pitch + x0, spans.last(y) - x0 + 1, static_cast<float>(dx * lx + dy * ly) * inv_len2,
          static_cast<float>(dx * rx + dy * ry) * inv_len2);
    }
  }
  if (visited) *visited += count;
  return ok;
}

// The float scan of `region`'s nodes against t's interpolation (triangle_scan.h's within_budget):
// a whole triangle of a shape tabled in groups by group_scan(), any other by rows.
template <class W>
bool scan_triangle(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets, float largest,
                   const Tri& t, const TriCorners* c, const Tri& region, long long* visited) {
  const std::ptrdiff_t pitch = static_cast<std::ptrdiff_t>(grid.cols());
  const ShapeTable* tabled =
      shape_table(region.left.x - region.apex.x, region.left.y - region.apex.y, region.right.x - region.apex.x,
                  region.right.y - region.apex.y, pitch);
  const bool whole = region.apex == t.apex && region.left == t.left && region.right == t.right;
  if constexpr (W::width == 8) {  // two row pieces of four a group
    if (whole && tabled && tabled->grouped) {
      long long count = 0;
      const WorldLegs legs = c ? world_legs(*c) : world_legs(grid, p, t);
      const bool ok = group_scan<W>(grid, p, budgets, t, c, *tabled, t.apex.y * pitch + t.apex.x, legs,
                                    scan_slack(largest), &count);
      if (visited) *visited += count;
      return ok;
    }
  }
  return scan_by_rows<W>(grid, p, budgets, largest, t, c ? *c : corners_of(grid, p, t), region, tabled, whole, visited);
}

// sure2 = max(budget - slack, 0)^2 * (1 - 1e-6) for the n nodes, W::width at a time (the last
// group's lanes past n into the padding): scan_thresholds() of triangle_scan.h.
template <class W>
void scan_thresholds_with(const float* budget, std::size_t n, float largest, float* sure2) {
  const typename W::F slack = W::set1(scan_slack(largest)), shrink = W::set1(1 - 1e-6f), zero = W::set1(0);
  for (std::size_t k = 0; k < n; k += W::width) {
    const typename W::F low = W::max_of(W::sub(W::load(budget + k), slack), zero);
    W::store(sure2 + k, W::mul(W::mul(low, low), shrink));
  }
}

}  // namespace POND_ISA
}  // namespace pond::lod
