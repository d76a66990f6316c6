#include "app/demo/picking.h"

#include <cmath>
#include <numbers>

namespace pond::app::demo {
namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec normalized(const Vec& a) {
  const double l = std::sqrt(dot(a, a));
  return l > 0 ? Vec{a[0] / l, a[1] / l, a[2] / l} : a;
}

// Möller–Trumbore, two-sided (the surface may fold over in an explosion). Returns t and the
// barycentric (u, v) of p1 and p2.
bool hit_triangle(const Ray& ray, const Vec& p0, const Vec& p1, const Vec& p2, double& t, double& u, double& v) {
  const Vec e1 = sub(p1, p0), e2 = sub(p2, p0);
  const Vec p = cross(ray.direction, e2);
  const double det = dot(e1, p);
  if (std::fabs(det) < 1e-12) return false;
  const double inv = 1.0 / det;
  const Vec s = sub(ray.origin, p0);
  u = dot(s, p) * inv;
  if (u < 0 || u > 1) return false;
  const Vec q = cross(s, e1);
  v = dot(ray.direction, q) * inv;
  if (v < 0 || u + v > 1) return false;
  t = dot(e2, q) * inv;
  return t > 0;
}

}  // namespace

Ray pixel_ray(const lod::Camera& camera, double x, double y) {
  const Vec forward = normalized(sub(camera.target, camera.eye));
  Vec right = cross(forward, Vec{0, 1, 0});
  if (dot(right, right) < 1e-12) right = {1, 0, 0};  // looking straight along y
  right = normalized(right);
  const Vec up = cross(right, forward);
  const double tan_y = std::tan(camera.fovy_degrees * std::numbers::pi / 360.0);
  const double tan_x = tan_y * camera.width / std::max(1, camera.height);
  const double nx = 2.0 * x / std::max(1, camera.width) - 1.0;
  const double ny = 1.0 - 2.0 * y / std::max(1, camera.height);
  Vec d;
  for (int k = 0; k < 3; ++k) d[k] = forward[k] + right[k] * nx * tan_x + up[k] * ny * tan_y;
  return Ray{camera.eye, normalized(d)};
}

std::optional<SurfaceHit> intersect_surface(const Ray& ray, const sim::WaterModel& model,
                                           const sim::HostDisplacements& at) {
  const int rows = model.rows, cols = model.cols;
  const double h = model.spacing;
  auto node = [&](int i, int j) {
    const std::size_t n = static_cast<std::size_t>(i) * at.pitch + static_cast<std::size_t>(j);
    return Vec{(static_cast<double>(j) + at.ux[n]) * h, at.uy[n] * h, (static_cast<double>(i) + at.uz[n]) * h};
  };
  std::optional<SurfaceHit> best;
  for (int i = 0; i + 1 < rows; ++i) {
    for (int j = 0; j + 1 < cols; ++j) {
      const Vec a = node(i, j), b = node(i, j + 1), c = node(i + 1, j), d = node(i + 1, j + 1);
      double t = 0, u = 0, v = 0;
      // Cell (i, j) as two triangles a-b-c and d-c-b; (u, v) are the weights of the 2nd and 3rd.
      if (hit_triangle(ray, a, b, c, t, u, v) && (!best || t < best->distance))
        best = SurfaceHit{.row = i + v, .col = j + u, .distance = t};
      if (hit_triangle(ray, d, c, b, t, u, v) && (!best || t < best->distance))
        best = SurfaceHit{.row = i + 1 - v, .col = j + 1 - u, .distance = t};
    }
  }
  return best;
}

std::optional<std::size_t> pick_sphere(const Ray& ray, std::span<const Sphere> spheres) {
  std::optional<std::size_t> best;
  double best_t = 0;
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    // |o + t d - c|^2 = r^2 with |d| = 1: t^2 + 2 b t + c2 = 0; the nearer root in front.
    const Vec oc = sub(ray.origin, spheres[k].centre);
    const double b = dot(oc, ray.direction);
    const double c2 = dot(oc, oc) - spheres[k].radius * spheres[k].radius;
    const double disc = b * b - c2;
    if (disc < 0) continue;
    const double root = std::sqrt(disc);
    const double t = -b - root >= 0 ? -b - root : -b + root;  // from inside: the far side
    if (t < 0) continue;
    if (!best || t < best_t) best = k, best_t = t;
  }
  return best;
}

std::optional<std::array<double, 3>> intersect_height(const Ray& ray, double height) {
  if (std::fabs(ray.direction[1]) < 1e-9) return std::nullopt;
  const double t = (height - ray.origin[1]) / ray.direction[1];
  if (t <= 0) return std::nullopt;
  return Vec{ray.origin[0] + t * ray.direction[0], height, ray.origin[2] + t * ray.direction[2]};
}

}  // namespace pond::app::demo
