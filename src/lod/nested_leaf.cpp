// A whole-grid leaf judged on its nested bounds (error_bounds.h): proved by its midpoint's bound,
// rejected by a quick look at its edges' midpoints, or proved by parts, and only the parts left
// unproved scanned. The grid read in blocks has no nested bounds: its triangles are scanned whole
// (LodBuilder::leaf_is_fine).
#include <cmath>

#include "lod/error_bounds.h"
#include "lod/lod_builder.h"
#include "lod/triangle_scan.h"

namespace pond::lod {

bool LodBuilder::nested_leaf_is_fine(const SurfaceBlock& blk, const Tri& t, Point mid_point) {
  const GridHierarchy& grid = *blk.grid;
  const NestedBound* bounds = blk.bounds.data();
  const float *px = blk.x.data(), *py = blk.y.data(), *pz = blk.z.data(), *budget = blk.budget.data();
  if (const NestedBound& b = bounds[grid.id(mid_point)]; b.error <= b.min_budget) {
    ++stats_.proved;
    return true;
  }
  // Quick rejects: the midpoint, then the midpoints of the legs (the children's midpoints), each
  // against the interpolation of the edge it halves (in double: exact but for ~1e-15 relative).
  // Each gives the midpoint's squared deviation, or -1 when the edge is a cell diagonal: the proofs
  // by parts below build on them.
  const auto squared_deviation = [&](Point e0, Point e1) {
    const int sx = e0.x + e1.x, sy = e0.y + e1.y;
    if ((sx | sy) & 1) return -1.0;  // a cell diagonal: no node halfway
    const std::uint32_t v = grid.id({sx >> 1, sy >> 1}), a = grid.id(e0), b = grid.id(e1);
    const double dx = px[v] - 0.5 * (double(px[a]) + px[b]);
    const double dy = py[v] - 0.5 * (double(py[a]) + py[b]);
    const double dz = pz[v] - 0.5 * (double(pz[a]) + pz[b]);
    return dx * dx + dy * dy + dz * dz;
  };
  const auto over = [&](double d2, Point e0, Point e1) {
    if (d2 < 0) return false;
    const double b = budget[grid.id({(e0.x + e1.x) / 2, (e0.y + e1.y) / 2})];
    return d2 > b * b;
  };
  const double mid2 = squared_deviation(t.left, t.right);
  if (over(mid2, t.left, t.right)) return false;
  const double left2 = squared_deviation(t.apex, t.left);
  if (over(left2, t.apex, t.left)) return false;
  const double right2 = squared_deviation(t.apex, t.right);
  if (over(right2, t.apex, t.right)) return false;

  // Proofs by parts. Split at m, t's children t1 = (m, apex, left) and t2 = (m, right, apex) are
  // triangles of the diamonds of the legs' midpoints c1, c2. A node p of t_i misses t's
  // interpolation by at most |p - I_ti(p)| + dev(m) (I_ti - I_t is linear on t_i, dev(m) at m and
  // zero at its other corners), so dev(m) + bound(c_i) <= min_budget(c_i) proves t_i. That is
  // sharper than the whole proof, which also takes the other triangle of m's diamond into its max
  // and min. A half that fails is tried once more by its own halves, the quarters split at c_i,
  // with dev(m) + dev(c_i) + bound(quarter's midpoint). A part without a midpoint (a half cell)
  // holds no node but its corners, and every corner of a part (t's corners, m, c1, c2) has been
  // checked above. Only the parts left unproved are scanned. Deviations are rounded up past the
  // double computation's error (~1e-15 relative) and the sums past their own rounding.
  const auto proved_by = [&](Point v, double deviations) {
    const NestedBound& b = bounds[grid.id(v)];
    return (deviations + b.error) * (1 + 1e-12) <= b.min_budget;
  };
  const double dev_m = deviation_up(mid2);
  Tri unproved[4];
  int parts = 0;
  const auto try_half = [&](const Tri& half, double leg2) {
    Point c;
    if (!midpoint(half, c) || proved_by(c, dev_m)) return;
    const double dev_mc = dev_m + deviation_up(leg2);
    const Tri quarter[2] = {child_left(half, c), child_right(half, c)};
    bool proved[2];
    for (int k = 0; k < 2; ++k) {
      Point d;
      proved[k] = !midpoint(quarter[k], d) || proved_by(d, dev_mc);
    }
    if (!proved[0] && !proved[1]) unproved[parts++] = half;
    else if (!proved[0]) unproved[parts++] = quarter[0];
    else if (!proved[1]) unproved[parts++] = quarter[1];
  };
  Point m{};
  midpoint(t, m);
  try_half(child_left(t, m), left2);
  try_half(child_right(t, m), right2);
  if (parts == 0) {
    ++stats_.proved;
    return true;
  }
  ++stats_.scanned;
  const NodePositions own = blk.positions();
  for (int k = 0; k < parts; ++k)
    if (!within_budget(grid, own, blk.scan_budgets(), largest_, t, unproved[k], &stats_.scanned_nodes))
      return false;
  return true;
}

// A deviation from its square (in double), rounded up past the double computation's error.
double LodBuilder::deviation_up(double d2) const { return std::sqrt(d2) * (1 + 1e-12) + 1e-12 * double(largest_); }

}  // namespace pond::lod
