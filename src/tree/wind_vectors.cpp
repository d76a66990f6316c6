#include "tree/wind_vectors.h"

#include <cmath>

namespace pond::tree {
namespace {

struct Vec3d {
  double x, y, z;
};
Vec3d cross(Vec3d a, Vec3d b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// sin(angle between branch and wind axis) below which they count as parallel.
constexpr double kParallelSine = 1e-6;

}  // namespace

float wind_stiffness_factor(float branch_length, int trunk_level, int level) {
  return branch_length * (0.3f + static_cast<float>(trunk_level - level));
}

Vec3 own_wind_vector(Vec3 dir, Vec3 axis, float s) {
  const Vec3d d{dir.x, dir.y, dir.z}, a{axis.x, axis.y, axis.z};
  const Vec3d across = cross(a, d);  // |across| = |dir| sin(angle), the axis being a unit vector
  const double dd = dot(d, d);
  if (dot(across, across) <= kParallelSine * kParallelSine * dd) return {};
  const Vec3d v = cross(d, across);  // = |dir|^2 * (axis minus its component along dir)
  const double scale = static_cast<double>(s) / std::sqrt(dot(v, v));
  return {static_cast<float>(v.x * scale), static_cast<float>(v.y * scale),
          static_cast<float>(v.z * scale)};
}

void compute_wind_vectors(Tree& tree) {
  constexpr Vec3 kAxisX{1.0f, 0.0f, 0.0f}, kAxisZ{0.0f, 0.0f, 1.0f};
  for (std::size_t i = 0; i < tree.size(); ++i) {
    TreeVertex& v = tree.vertices[i];
    const std::int32_t p = tree.parents[i];
    if (p == kNoParent) {  // the trunk's base never moves
      v.wind_x = {};
      v.wind_z = {};
      continue;
    }
    const TreeVertex& parent = tree.vertices[static_cast<std::size_t>(p)];
    const Vec3 dir = v.position - parent.position;
    const float s = wind_stiffness_factor(length(dir), tree.depth, tree.levels[i]);
    v.wind_x = parent.wind_x + own_wind_vector(dir, kAxisX, s);
    v.wind_z = parent.wind_z + own_wind_vector(dir, kAxisZ, s);
  }
}

}  // namespace pond::tree
