#include "tree/tree_lod.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pond::tree {
namespace {

using tree::Vec3;

Vec3 rest_position(const TreeMeshVertex& v) { return v.branch.position + Vec3{v.offset.x, v.offset.y, v.offset.z}; }

}  // namespace

TreeLodCamera tree_lod_camera(const float* m, int height) {
  TreeLodCamera c;
  c.depth_row = {m[3], m[7], m[11], m[15]};
  // Clip y is the projection's focal scale times view y, whose row is a unit vector.
  c.pixels_per_unit = 0.5f * static_cast<float>(height) * std::sqrt(m[1] * m[1] + m[5] * m[5] + m[9] * m[9]);
  return c;
}

TreeBounds tree_bounds(const tree::Tree& t, const TreeMesh& mesh) {
  TreeBounds b;
  Vec3 lo = rest_position(mesh.vertices.front()), hi = lo;
  float offset = 0.0f;
  for (const TreeMeshVertex& v : mesh.vertices) {
    const Vec3 p = rest_position(v);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    offset = std::max(offset, tree::length(Vec3{v.offset.x, v.offset.y, v.offset.z}));
  }
  b.rest.centre = (lo + hi) * 0.5f;
  for (const TreeMeshVertex& v : mesh.vertices)
    b.rest.radius = std::max(b.rest.radius, tree::length(rest_position(v) - b.rest.centre));

  b.root = t.vertices.front().position;
  std::vector<float> path(t.size(), 0.0f);  // parents come before their children
  float longest = 0.0f;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const auto p = static_cast<std::size_t>(t.parents[i]);
    path[i] = path[p] + tree::length(t.vertices[i].position - t.vertices[p].position);
    longest = std::max(longest, path[i]);
  }
  b.reach = longest + offset;
  for (const tree::TreeVertex& v : t.vertices) {
    b.wind_gain = std::max(b.wind_gain, tree::length(v.wind_x) + tree::length(v.wind_z));
    b.jitter_gain = std::max(b.jitter_gain, std::abs(v.jitter.x) + std::abs(v.jitter.y) + std::abs(v.jitter.z));
  }
  // Rounding: the bounds are sums of a few floats; a relative margin covers their last bits.
  b.rest.radius *= 1.001f;
  b.reach *= 1.001f;
  return b;
}

Sphere bent_bounds(const TreeBounds& b, const tree::TreeWindFrame& f) {
  const float q = std::max({std::abs(f.twig.x), std::abs(f.twig.y), std::abs(f.twig.z)});
  const float moved = b.wind_gain * (std::max(std::abs(f.wind.x), std::abs(f.wind.z)) + b.jitter_gain * q) * 1.001f;
  if (f.bend_mode == shared::tree_wind::kTreeBendKeepLength) return {b.root, b.reach + moved};
  return {b.rest.centre, b.rest.radius + moved};
}

float nearest_pixels_per_unit(const TreeLodCamera& c, const Sphere& s, float world_per_unit) {
  const float depth_of_centre =
      c.depth_row[0] * s.centre.x + c.depth_row[1] * s.centre.y + c.depth_row[2] * s.centre.z + c.depth_row[3];
  const float nearest = depth_of_centre - s.radius;
  if (nearest <= 0.0f) return std::numeric_limits<float>::infinity();
  return c.pixels_per_unit * world_per_unit / nearest;
}

int thinnest_tube_level(float pixels_per_unit, int depth) {
  for (int level = 1; level <= depth; ++level)
    if (2.0f * tree_tube_radius(depth, level) * pixels_per_unit >= kMinTubePixels) return level;
  return depth + 1;
}

Pruning prune(std::uint32_t n, float measure, float least) {
  if (n == 0 || !(measure < least)) return {n, 1.0f};
  const double wanted = std::ceil(static_cast<double>(n) * std::max(measure, 0.0f) / least);
  const auto count = static_cast<std::uint32_t>(std::clamp(wanted, 1.0, static_cast<double>(n)));
  return {count, static_cast<float>(n) / static_cast<float>(count)};
}

bool diamond_leaves(float pixels_per_unit, float longest_leaf) {
  return longest_leaf * pixels_per_unit >= kMinDiamondLeafPixels;
}

}  // namespace pond::tree
