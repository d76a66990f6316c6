#pragma once
// The camera of one frame and what it allows each node: the world distance by which a left-out
// node may miss its covering triangle. With the LOD screen-space error of the contract,
//   error_px = distance / depth * height / (2 tan(fovy / 2))  <=  tau
// is the same as distance <= tau * depth / K with K = height / (2 tan(fovy / 2)). Nodes outside
// the view frustum (behind the camera or projecting outside the viewport) may be left out freely:
// their budget is +infinity.
#include <algorithm>
#include <array>
#include <cstddef>

#include "lod/node_positions.h"

namespace pond::lod {

struct Camera {
  std::array<double, 3> eye{0, 10, 0};
  std::array<double, 3> target{0, 0, 1};
  double fovy_degrees = 60;
  int width = 1280, height = 720;
};

// Throws InputError naming the problem: non-finite values, fovy outside (0, 180), a zero
// viewport, eye == target, or tolerance not > 0.
void validate(const Camera& camera, double tolerance_px);

// The view basis. Up is world +y; looking straight up or down there is no roll defined, so the
// frustum is widened to the cone around the viewport's diagonal (conservative for any roll).
struct ViewBasis {
  std::array<double, 3> eye, forward, right, up;
  double tan_x = 0, tan_y = 0;  // half extents of the viewport at depth 1
  bool cone = false;            // true when looking along +-y
  double pixels_per_radian = 0;  // K = height / (2 tan(fovy / 2))
};
ViewBasis view_basis(const Camera& camera);

// One frame's budget terms, from the camera, tau and `largest` (a bound on every |coordinate|):
// depth and screen offsets computed in float are known within delta = 32 eps max(largest, |eye|),
// so the frustum is widened (by kFrustumSlack and delta) and the depth lowered by delta before
// the budget per_depth * depth is taken.
struct BudgetTerms {
  ViewBasis basis;
  double delta = 0, per_depth = 0;  // per_depth: tau / K, shrunk past the products' rounding
  double tan_x = 0, tan_y = 0;      // the widened frustum's half extents at depth 1
};
BudgetTerms budget_terms(const Camera& camera, double tolerance_px, float largest);

// The least budget of any node in a world box: +infinity when the box lies wholly outside the
// frustum (widened as the node budgets' is), else per_depth * (its least depth - 2 delta), never
// below 0. In double. Twice delta: node_budgets takes delta off a depth it computes in float (within
// a fraction of delta of the exact one), so this is at most every node's own float budget, and a
// region the box budgets prove holds no node an exact scan finds over its budget.
class BoxBudget {
 public:
  explicit BoxBudget(const BudgetTerms& terms);
  double least(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const;
  // error <= least(lo, hi), the depth's budget tried first: only a box it does not allow needs the
  // frustum's planes.
  bool allows(double error, const std::array<double, 3>& lo, const std::array<double, 3>& hi) const {
    return error <= depth_budget(lo, hi) || outside(lo, hi);
  }
  // The box lies inside the frustum by the margin (never when looking along +-y): every node in
  // it is in view for node_budgets too, whose float rounding the margin covers.
  bool inside(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const;

 private:
  // A linear function n . p + c of a world point: its extremes over a box lie at the corners the
  // signs of n pick, so each takes one evaluation rather than eight. `upper[i]`: n[i] > 0, the
  // coordinate the largest takes from the box's upper corner (an index, not a branch).
  struct Plane {
    double n[3], c;
    int upper[3];
    double largest(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const {
      const double* corner[2] = {lo.data(), hi.data()};
      return n[0] * corner[upper[0]][0] + n[1] * corner[upper[1]][1] + n[2] * corner[upper[2]][2] + c;
    }
    double smallest(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const {
      return largest(hi, lo);  // the corner of the other signs
    }
  };
  bool outside(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const;
  double depth_budget(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const {
    return t_.per_depth * std::max(depth_.smallest(lo, hi) - 2 * t_.delta, 0.0);
  }
  BudgetTerms t_;
  Plane depth_;
  Plane sides_[4];  // tan_x depth -+ sx and tan_y depth -+ sy: >= 0 inside the frustum
  double margin_ = 0;
};

// Writes budget[n] (world units) for every node of `positions` (stride 1). Computed in float
// (vectorized) and kept conservative, with `terms` (of a `largest` bounding every |coordinate| of
// the positions). With `wide`, by the AVX2 copy where wide_budgets_available(): the same bits
// (callers pass core::cpu_has(avx2), so that POND_CPU_FEATURES_MASK can hide it).
// With `all_in_view` (BoxBudget::inside of a box holding every node), the frustum's tests are
// skipped: the same bits.
void node_budgets(const NodePositions& positions, const BudgetTerms& terms, float* budget, bool wide = true,
                  bool all_in_view = false);
// This build has node_budgets' AVX2 copy (not IA-32) and this CPU can run it.
bool wide_budgets_available();

}  // namespace pond::lod
