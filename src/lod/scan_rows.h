#pragma once
// The exact scan's float pass (triangle_scan.h), built twice like the node budgets (budget_loop.h):
// by triangle_scan.cpp with SSE2 lanes, four nodes a group, and by triangle_scan_avx2.cpp with
// AVX2 lanes, eight. The AVX2 copy scans a whole small triangle in groups of row pieces instead
// (group_scan). Every path decides in float only the nodes float rounding cannot mislead (inside
// the slack of scan_by_rows()'s analysis) and the others by the same test in double, so all give
// the same verdicts. Its templates are in an unnamed namespace: each file keeps its own copy, not
// the linker's pick.
//
// L, the lanes: a vector type V of L::width floats, and set1, splat<i> (lane i of an __m128 in
// every lane), iota (0, 1, ...), load (unaligned), add, sub, mul, and_, or_, less and greater (lane
// masks), any (a mask has a lane set); `pairs` says whether it has group_scan's load_pair (two
// four-float loads, one a half), load_mask and lane (lane k of a mask is set).
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include <xmmintrin.h>  // a row's first value, its three coordinates in one vector

#include "lod/grid_hierarchy.h"
#include "lod/node_positions.h"
#include "lod/triangle_scan.h"

namespace pond::lod {

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
// lane for lane, so the same bits.
bool scan_triangle_avx2(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets, float largest,
                        const Tri& t, const TriCorners* c, const Tri& region, long long* visited);
void scan_thresholds_avx2(const float* budget, std::size_t n, float largest, float* sure2);
#endif

namespace {

// The rows of the triangle with legs (lx, ly) and (rx, ry) in arrays of `pitch` floats a row, or
// nullptr for legs the tables do not hold. Each thread, and each copy of the scan, keeps the
// tables of its last four pitches: a frame's blocks have one or two (the grid's last blocks may be
// narrower), the whole grid its own, and a view may switch between the two from frame to frame.
struct ShapeTables {
  std::ptrdiff_t pitch = -1;
  std::vector<ShapeTable> shapes;
};
constexpr int kPitches = 4;
thread_local ShapeTables shape_tables[kPitches];

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

// A triangle's interpolation for the row scan: the apex and the legs in world space (x, y, z, 0),
// and as vectors built once per triangle, how much the interpolation moves per column and the
// budgets' rounding slack. Along a row it is linear, so a row needs its first node's value only.
template <class L>
struct ScanPlane {
  __m128 a, l, r;
  typename L::V step[3];
  typename L::V slack;
};

struct RowVerdict {
  bool over;   // a node is over its budget for sure
  bool close;  // a node is so near its budget that float cannot tell
};

// The squared misses of a row's nodes k .. k + L::width - 1 (kf: those k as floats) from the
// interpolation, which is `first` at the row's first node and moves by a step per column.
template <class L>
inline typename L::V squared_miss(const float* px, const float* py, const float* pz, int k, typename L::V kf,
                                  const typename L::V first[3], const ScanPlane<L>& r) {
  using V = typename L::V;
  const V ex = L::sub(L::load(px + k), L::add(first[0], L::mul(kf, r.step[0])));
  const V ey = L::sub(L::load(py + k), L::add(first[1], L::mul(kf, r.step[1])));
  const V ez = L::sub(L::load(pz + k), L::add(first[2], L::mul(kf, r.step[2])));
  return L::add(L::add(L::mul(ex, ex), L::mul(ey, ey)), L::mul(ez, ez));
}

// The nodes k = 0 .. len-1 of a row, L::width at a time. The last group's lanes past the row read
// the following nodes (or the arrays' padding) and are masked out, so there is no scalar tail.
// First, one compare a node: is any miss over its sure-within threshold (scan_thresholds())? Only
// a row where one is gets the exact test, which tells a node surely over from one too close to call.
template <class L>
RowVerdict scan_row(const float* px, const float* py, const float* pz, const ScanBudgets& budgets, int len,
                    const typename L::V first[3], const ScanPlane<L>& r) {
  using V = typename L::V;
  const V zero = L::set1(0), width = L::set1(L::width), end = L::set1(static_cast<float>(len));
  V maybe = zero, kf = L::iota();  // exact integers
  for (int k = 0; k < len; k += L::width, kf = L::add(kf, width)) {
    const V e2 = L::and_(L::less(kf, end), squared_miss<L>(px, py, pz, k, kf, first, r));  // 0 past the row
    maybe = L::or_(maybe, L::greater(e2, L::load(budgets.sure2 + k)));
  }
  if (!L::any(maybe)) return {false, false};
  const V grow = L::set1(1 + 1e-6f);
  V over = zero, close = zero;
  kf = L::iota();
  for (int k = 0; k < len; k += L::width, kf = L::add(kf, width)) {
    const V live = L::less(kf, end);
    const V e2 = squared_miss<L>(px, py, pz, k, kf, first, r);
    const V high = L::add(L::load(budgets.budget + k), r.slack);
    over = L::or_(over, L::and_(live, L::greater(e2, L::mul(L::mul(high, high), grow))));
    close = L::or_(close, L::and_(live, L::greater(e2, L::load(budgets.sure2 + k))));
  }
  return {L::any(over), L::any(close)};
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
template <class L>
bool group_scan(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets, const Tri& t,
                const TriCorners* c, const ShapeTable& table, std::ptrdiff_t apex, const WorldLegs& legs, float slack,
                long long* count) {
  using V = typename L::V;
  static_assert(L::width == 8);
  const float *px = p.x + apex, *py = p.y + apex, *pz = p.z + apex, *sure2 = budgets.sure2 + apex;
  const ShapeGroup* g = table.groups.data();
  const ShapeGroup* const end = g + table.groups.size();
  while (g != end) {
    // The groups up to the next one with a node float cannot call within, with the interpolation's
    // terms in registers: no call in this loop, so none of them is saved around one.
    const V ax = L::set1(legs.a[0]), ay = L::set1(legs.a[1]), az = L::set1(legs.a[2]);
    const V lx = L::set1(legs.l[0]), ly = L::set1(legs.l[1]), lz = L::set1(legs.l[2]);
    const V rx = L::set1(legs.r[0]), ry = L::set1(legs.r[1]), rz = L::set1(legs.r[2]);
    V e2 = L::set1(0), close = e2;
    for (; g != end; ++g) {
      const std::int32_t lo = g->offset[0], hi = g->offset[1];
      const V u = L::load(g->u), w = L::load(g->w), live = L::load_mask(g->live);
      const V ex = L::sub(L::load_pair(px + lo, px + hi), L::add(L::add(ax, L::mul(u, lx)), L::mul(w, rx)));
      const V ey = L::sub(L::load_pair(py + lo, py + hi), L::add(L::add(ay, L::mul(u, ly)), L::mul(w, ry)));
      const V ez = L::sub(L::load_pair(pz + lo, pz + hi), L::add(L::add(az, L::mul(u, lz)), L::mul(w, rz)));
      e2 = L::and_(live, L::add(L::add(L::mul(ex, ex), L::mul(ey, ey)), L::mul(ez, ez)));  // 0 off the triangle
      close = L::greater(e2, L::load_pair(sure2 + lo, sure2 + hi));
      if (L::any(close)) break;
    }
    if (g == end) break;
    // Group g has a node near its budget: over for sure, or decided in double.
    const std::int32_t lo = g->offset[0], hi = g->offset[1];
    const auto fail = [&] {
      *count += g->through;
      return false;
    };
    const float* budget = budgets.budget + apex;
    const V high = L::add(L::load_pair(budget + lo, budget + hi), L::set1(slack));
    if (L::any(L::greater(e2, L::mul(L::mul(high, high), L::set1(1 + 1e-6f))))) return fail();
    const std::ptrdiff_t pitch = static_cast<std::ptrdiff_t>(grid.cols());
    const TriCorners corners = c ? *c : corners_of(grid, p, t);
    for (int k = 0; k < L::width; ++k) {
      if (!L::lane(close, k)) continue;
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
template <class L>
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
  ScanPlane<L> plane;
  for (int i = 0; i < 3; ++i) plane.step[i] = L::set1(du * legs.l[i] + dw * legs.r[i]);
  plane.a = _mm_setr_ps(legs.a[0], legs.a[1], legs.a[2], 0), plane.l = _mm_setr_ps(legs.l[0], legs.l[1], legs.l[2], 0);
  plane.r = _mm_setr_ps(legs.r[0], legs.r[1], legs.r[2], 0);
  plane.slack = L::set1(slack);
  bool ok = true;
  // Each row is tested whole (no early exit inside, it goes L::width nodes at a time), a row float
  // cannot decide once more in double, and the scan stops after the first row with a node over.
  const auto row = [&](std::ptrdiff_t base, int len, float u0, float w0) {
    // The row's first value a + u0 l + w0 r, the three coordinates at once, each rounded as alone.
    const __m128 f = _mm_add_ps(_mm_add_ps(plane.a, _mm_mul_ps(_mm_set1_ps(u0), plane.l)),
                                _mm_mul_ps(_mm_set1_ps(w0), plane.r));
    const typename L::V first[3] = {L::template splat<0>(f), L::template splat<1>(f), L::template splat<2>(f)};
    const RowVerdict v = scan_row<L>(p.x + base, p.y + base, p.z + base,
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
template <class L>
bool scan_triangle(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets, float largest,
                   const Tri& t, const TriCorners* c, const Tri& region, long long* visited) {
  const std::ptrdiff_t pitch = static_cast<std::ptrdiff_t>(grid.cols());
  const ShapeTable* tabled =
      shape_table(region.left.x - region.apex.x, region.left.y - region.apex.y, region.right.x - region.apex.x,
                  region.right.y - region.apex.y, pitch);
  const bool whole = region.apex == t.apex && region.left == t.left && region.right == t.right;
  if constexpr (L::pairs) {
    if (whole && tabled && tabled->grouped) {
      long long count = 0;
      const WorldLegs legs = c ? world_legs(*c) : world_legs(grid, p, t);
      const bool ok = group_scan<L>(grid, p, budgets, t, c, *tabled, t.apex.y * pitch + t.apex.x, legs,
                                    scan_slack(largest), &count);
      if (visited) *visited += count;
      return ok;
    }
  }
  return scan_by_rows<L>(grid, p, budgets, largest, t, c ? *c : corners_of(grid, p, t), region, tabled, whole, visited);
}

}  // namespace
}  // namespace pond::lod
