#include "lod/camera_budget.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "lod/budget_loop.h"

namespace pond::lod {
namespace {

using Vec = std::array<double, 3>;
Vec add(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec scale(const Vec& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

// The frustum is widened by this relative amount so that a node a double-precision checker finds
// just inside the viewport is never treated as outside.
constexpr double kFrustumSlack = 1e-4;
// Budgets shrink by this much: the few float products of a budget round by 6e-8 relative each.
constexpr double kBudgetShrink = 1 - 1e-5;

}  // namespace

void validate(const Camera& c, double tolerance_px) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(c.eye[k]) || !std::isfinite(c.target[k]))
      throw InputError("camera eye and target must be finite");
  if (c.eye == c.target) throw InputError("camera eye and target must differ");
  if (!(c.fovy_degrees > 0 && c.fovy_degrees < 180))
    throw InputError("fovy " + std::to_string(c.fovy_degrees) + " must be in (0, 180) degrees");
  if (c.width <= 0 || c.height <= 0) throw InputError("viewport size must be at least 1x1");
  if (!(tolerance_px > 0) || !std::isfinite(tolerance_px))
    throw InputError("tolerance " + std::to_string(tolerance_px) + " must be > 0 pixels");
}

ViewBasis view_basis(const Camera& c) {
  ViewBasis b;
  b.eye = c.eye;
  const Vec f = sub(c.target, c.eye);
  b.forward = scale(f, 1 / std::sqrt(dot(f, f)));
  Vec r = cross(b.forward, {0, 1, 0});
  const double rl = std::sqrt(dot(r, r));
  if (rl < 1e-9) {
    b.cone = true;
    r = {1, 0, 0};
  } else {
    r = scale(r, 1 / rl);
  }
  b.right = r;
  b.up = cross(r, b.forward);
  b.tan_y = std::tan(c.fovy_degrees * std::numbers::pi / 360);
  b.tan_x = b.tan_y * c.width / c.height;
  b.pixels_per_radian = c.height / (2 * b.tan_y);
  return b;
}

BudgetTerms budget_terms(const Camera& c, double tolerance_px, float largest) {
  BudgetTerms t;
  t.basis = view_basis(c);
  const double eye_max = std::max({std::abs(c.eye[0]), std::abs(c.eye[1]), std::abs(c.eye[2])});
  t.delta = 32 * std::max(double(largest), eye_max) * std::numeric_limits<float>::epsilon();
  t.per_depth = tolerance_px / t.basis.pixels_per_radian * kBudgetShrink;
  t.tan_x = t.basis.tan_x * (1 + kFrustumSlack), t.tan_y = t.basis.tan_y * (1 + kFrustumSlack);
  return t;
}

BoxBudget::BoxBudget(const BudgetTerms& terms) : t_(terms) {
  const ViewBasis& b = t_.basis;
  // n . (p - eye) for n = forward, and the four side planes' normals.
  const auto plane = [&](const Vec& n) {
    return Plane{{n[0], n[1], n[2]}, -dot(n, b.eye), {n[0] > 0, n[1] > 0, n[2] > 0}};
  };
  depth_ = plane(b.forward);
  const Vec fx = scale(b.forward, t_.tan_x), fy = scale(b.forward, t_.tan_y);
  sides_[0] = plane(sub(fx, b.right)), sides_[1] = plane(add(fx, b.right));
  sides_[2] = plane(sub(fy, b.up)), sides_[3] = plane(add(fy, b.up));
  // Far above the double rounding here and the float rounding of node_budgets.
  margin_ = 4 * t_.delta * (1 + t_.tan_x + t_.tan_y);
}

bool BoxBudget::outside(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const {
  // The box is outside when it lies wholly outside one plane (depth > 0, |sx| <= tx depth,
  // |sy| <= ty depth) by the margin. Looking along +-y the roll is free (view_basis): only the
  // depth plane culls.
  bool out = depth_.largest(lo, hi) <= -margin_;
  if (!t_.basis.cone)
    for (const Plane& side : sides_) out = out || side.largest(lo, hi) <= -margin_;
  return out;
}

bool BoxBudget::inside(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const {
  if (t_.basis.cone || depth_.smallest(lo, hi) < margin_) return false;
  for (const Plane& side : sides_)
    if (side.smallest(lo, hi) < margin_) return false;
  return true;
}

double BoxBudget::least(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const {
  return outside(lo, hi) ? std::numeric_limits<double>::infinity() : depth_budget(lo, hi);
}

bool wide_budgets_available() {
#if POND_LOD_AVX2
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

void node_budgets(const NodePositions& p, const BudgetTerms& t, float* budget, [[maybe_unused]] bool wide,
                  bool all_in_view) {
#if POND_LOD_AVX2
  if (wide && wide_budgets_available()) return node_budgets_avx2(p, t, budget, all_in_view);
#endif
  budget_loop(p, t, budget, all_in_view);
}

}  // namespace pond::lod
