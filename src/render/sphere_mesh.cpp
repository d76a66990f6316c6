#include "render/sphere_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace pond::render {
namespace {

using Point = std::array<double, 3>;

Point unit(const Point& p) {
  const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {p[0] / l, p[1] / l, p[2] / l};
}

}  // namespace

SphereMesh build_sphere_mesh(int subdivisions) {
  // The icosahedron: the corners of three golden rectangles, faces counter-clockwise from outside.
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Point> points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                               {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Point& p : points) p = unit(p);
  std::vector<std::array<std::uint32_t, 3>> faces = {
      {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
      {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;  // one per shared edge
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      const Point& p = points[a];
      const Point& q = points[b];
      points.push_back(unit({p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
      const auto index = static_cast<std::uint32_t>(points.size() - 1);
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    finer.reserve(faces.size() * 4);
    for (const auto& [a, b, c] : faces) {
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    faces = std::move(finer);
  }
  SphereMesh mesh;
  for (const Point& p : points)
    mesh.points.push_back({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]), 1.0f});
  for (const auto& f : faces) mesh.indices.insert(mesh.indices.end(), f.begin(), f.end());
  return mesh;
}

double longest_edge(const SphereMesh& mesh) {
  double longest = 0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const auto& a = mesh.points[mesh.indices[t + k]];
      const auto& b = mesh.points[mesh.indices[t + (k + 1) % 3]];
      const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
      longest = std::max(longest, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  return longest;
}

double outline_error_px(double radius_px, double edge) {
  return radius_px * (1.0 - std::sqrt(std::max(0.0, 1.0 - 0.25 * edge * edge)));
}

}  // namespace pond::render
