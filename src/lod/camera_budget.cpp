#include "lod/camera_budget.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.h"

namespace pond::lod {
namespace {

using Vec = std::array<double, 3>;
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec scale(const Vec& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

// The frustum is widened by this relative amount so that a node a double-precision checker finds
// just inside the viewport is never treated as outside.
constexpr double kFrustumSlack = 1e-4;
// Budgets shrink by this much: float storage of a budget rounds by 6e-8 relative.
constexpr double kBudgetShrink = 1 - 1e-6;

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

void node_budgets(const NodePositions& p, const Camera& c, double tolerance_px, float* budget) {
  const ViewBasis b = view_basis(c);
  const double tx = b.tan_x * (1 + kFrustumSlack), ty = b.tan_y * (1 + kFrustumSlack);
  const double cone2 = tx * tx + ty * ty;
  const double per_depth = tolerance_px / b.pixels_per_radian * kBudgetShrink;
  const float infinite = std::numeric_limits<float>::infinity();
  const std::size_t n = p.nodes(), st = p.stride;
  const double ex = b.eye[0], ey = b.eye[1], ez = b.eye[2];
  const double f0 = b.forward[0], f1 = b.forward[1], f2 = b.forward[2];
  const double r0 = b.right[0], r1 = b.right[1], r2 = b.right[2];
  const double u0 = b.up[0], u1 = b.up[1], u2 = b.up[2];
  // Branch-free bodies (& rather than &&) so the compiler can vectorize; the cone case apart.
  if (b.cone) {
    for (std::size_t k = 0; k < n; ++k) {
      const double dx = p.x[k * st] - ex, dy = p.y[k * st] - ey, dz = p.z[k * st] - ez;
      const double depth = dx * f0 + dy * f1 + dz * f2;
      const double sx = dx * r0 + dy * r1 + dz * r2, sy = dx * u0 + dy * u1 + dz * u2;
      const bool in_view = (depth > 0) & (sx * sx + sy * sy <= cone2 * depth * depth);
      budget[k] = in_view ? static_cast<float>(per_depth * depth) : infinite;
    }
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double dx = p.x[k * st] - ex, dy = p.y[k * st] - ey, dz = p.z[k * st] - ez;
    const double depth = dx * f0 + dy * f1 + dz * f2;
    const double sx = dx * r0 + dy * r1 + dz * r2, sy = dx * u0 + dy * u1 + dz * u2;
    const bool in_view = (depth > 0) & (std::abs(sx) <= tx * depth) & (std::abs(sy) <= ty * depth);
    budget[k] = in_view ? static_cast<float>(per_depth * depth) : infinite;
  }
}

}  // namespace pond::lod
