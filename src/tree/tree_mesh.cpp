#include "tree/tree_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pond::tree {
namespace {

namespace sh = shared::tree_wind;
using tree::Vec3;

constexpr float kTrunkRadius = 0.065f;
constexpr float kRadiusRatio = 0.62f;
// Sides per ring: six where a branch is thick enough to show its roundness, four for the two
// thinnest levels (2/3 of all segments, a pixel or two wide at any sensible distance).
constexpr int kSidesThick = 6, kSidesThin = 4;
// A leaf is a diamond this many times its twig's length long and wide.
constexpr float kLeafLength = 1.1f, kLeafWidth = 0.6f;

int tube_sides(int level) { return level <= 2 ? kSidesThin : kSidesThick; }

sh::vec4 v4(Vec3 a) { return {a.x, a.y, a.z, 0.0f}; }

// A unit vector perpendicular to unit `d`: crossed with the axis it is least aligned with.
Vec3 perpendicular(Vec3 d) {
  const float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  const Vec3 axis = ax <= ay && ax <= az ? Vec3{1, 0, 0} : ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  return tree::normalize(tree::cross(d, axis));
}

// A small deterministic hash (splitmix-style) for the leaves' shade variation.
std::uint32_t hash(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// GLSL's packSnorm4x8 of (v, 0): each component rounded to a signed byte, x in the low byte.
std::uint32_t pack_snorm4x8(Vec3 v) {
  auto byte = [](float c) {
    return static_cast<std::uint32_t>(static_cast<std::uint8_t>(static_cast<std::int8_t>(std::lround(std::clamp(c, -1.0f, 1.0f) * 127.0f))));
  };
  return byte(v.x) | byte(v.y) << 8 | byte(v.z) << 16;
}

// The order of a fixed shuffle of the skeleton's vertices (ties broken by the index).
std::uint64_t shuffle_key(std::size_t i) {
  return (std::uint64_t{hash(static_cast<std::uint32_t>(i) ^ 0x9e3779b9u)} << 32) | i;
}

TreeMeshVertex mesh_vertex(const tree::Tree& t, std::size_t branch, Vec3 offset, Vec3 normal,
                           std::uint32_t material, std::uint32_t shade = 0) {
  TreeMeshVertex v;
  v.branch = t.vertices[branch];
  v.offset = v4(offset);
  v.normal = v4(normal);
  v.info = {static_cast<std::uint32_t>(branch), material, shade, 0};
  return v;
}

}  // namespace

float tree_tube_radius(int depth, int level) {
  return kTrunkRadius * std::pow(kRadiusRatio, static_cast<float>(depth - level));
}

IndexRange LevelRange::at_least(int level) const {
  const auto end = level_end[static_cast<std::size_t>(std::clamp(level, 0, static_cast<int>(level_end.size()) - 1))];
  return {all.first, end};
}

IndexRange LevelRange::below(int level) const {
  const IndexRange thick = at_least(level);
  return {all.first + thick.count, all.count - thick.count};
}

IndexRange LevelRange::level(int level) const {
  const IndexRange thick = at_least(level + 1), with = at_least(level);
  return {all.first + thick.count, with.count - thick.count};
}

TreeMesh build_tree_mesh(const tree::Tree& t) {
  TreeMesh m;
  const std::size_t n = t.size();
  for (std::size_t i = 0; i < n; ++i) m.rest_height = std::max(m.rest_height, t.vertices[i].position.y);

  // The segments (by their tip vertex), the trunk's level first; within a level in the order of a
  // hash of the tip (a fixed shuffle: any prefix of a level is a uniform sample of it).
  std::vector<std::size_t> segments;
  for (std::size_t i = 1; i < n; ++i) segments.push_back(i);
  std::sort(segments.begin(), segments.end(), [&](std::size_t a, std::size_t b) {
    if (t.levels[a] != t.levels[b]) return t.levels[a] > t.levels[b];
    return shuffle_key(a) < shuffle_key(b);
  });
  // Marks the end of each level in `r` as the segments are added: level_end[L] = indices so far
  // once every segment of level >= L is in.
  auto close_levels = [&](LevelRange& r, int from_level, int to_level) {
    for (int l = from_level; l > to_level; --l) r.level_end[static_cast<std::size_t>(l)] = static_cast<std::uint32_t>(m.indices.size()) - r.all.first;
  };

  // Lines: vertex i is skeleton vertex i.
  for (std::size_t i = 0; i < n; ++i) m.vertices.push_back(mesh_vertex(t, i, {}, {}, sh::kTreeMaterialLine));
  m.lines.all.first = 0;
  m.lines.level_end.assign(static_cast<std::size_t>(t.depth) + 2, 0);
  int level = t.depth;
  for (std::size_t i : segments) {
    close_levels(m.lines, level, t.levels[i]);
    level = t.levels[i];
    m.indices.insert(m.indices.end(), {static_cast<std::uint32_t>(t.parents[i]), static_cast<std::uint32_t>(i)});
  }
  m.lines.all.count = static_cast<std::uint32_t>(m.indices.size());
  close_levels(m.lines, level, -1);

  // Twig lines: the same lines over a second copy of the skeleton's vertices (drawn with
  // vertexOffset = twig_vertices), which carries what the level of detail's thin lines shade with.
  m.twig_vertices = static_cast<std::int32_t>(m.vertices.size());
  for (std::size_t i = 0; i < n; ++i) {
    // The segment ending here (the trunk's for the root) gives the direction, and the width is its
    // tube's here (a segment tapers to its children's base radius at its tip), as seen on average
    // from any side: a convex section's mean width is its perimeter / pi.
    const std::size_t seg = i == 0 ? 1 : i;
    const Vec3 d = tree::normalize(t.vertices[seg].position - t.vertices[static_cast<std::size_t>(t.parents[seg])].position);
    TreeMeshVertex v = mesh_vertex(t, i, {}, d, sh::kTreeMaterialTwig);
    const float sides = static_cast<float>(tube_sides(t.levels[seg]));
    const float radius = tree_tube_radius(t.depth, i == 0 ? t.depth : t.levels[i] - 1);
    v.offset.w = sides * 2.0f * radius * std::sin(std::numbers::pi_v<float> / sides) / std::numbers::pi_v<float>;
    m.vertices.push_back(v);
  }

  // Tubes.
  m.tubes.all.first = static_cast<std::uint32_t>(m.indices.size());
  m.tubes.level_end.assign(static_cast<std::size_t>(t.depth) + 2, 0);
  level = t.depth;
  for (std::size_t i : segments) {
    close_levels(m.tubes, level, t.levels[i]);
    level = t.levels[i];
    const auto p = static_cast<std::size_t>(t.parents[i]);
    const Vec3 dir = t.vertices[i].position - t.vertices[p].position;
    const Vec3 d = tree::normalize(dir);
    const Vec3 u = perpendicular(d), w = tree::cross(d, u);
    const int sides = tube_sides(level);
    const float r_base = tree_tube_radius(t.depth, level), r_tip = tree_tube_radius(t.depth, level - 1);
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (int ring = 0; ring < 2; ++ring) {
      const float r = ring == 0 ? r_base : r_tip;
      for (int k = 0; k < sides; ++k) {
        const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / static_cast<float>(sides);
        const Vec3 normal = u * std::cos(a) + w * std::sin(a);
        m.vertices.push_back(mesh_vertex(t, ring == 0 ? p : i, normal * r, normal, sh::kTreeMaterialBark));
      }
    }
    // (u, w, d) is right-handed, so k -> k + 1 turns counter-clockwise seen from outside.
    const auto s = static_cast<std::uint32_t>(sides);
    for (std::uint32_t k = 0; k < s; ++k) {
      const std::uint32_t a = base + k, b = base + (k + 1) % s, c = a + s, e = b + s;
      m.indices.insert(m.indices.end(), {a, b, e, a, e, c});
    }
  }
  m.tubes.all.count = static_cast<std::uint32_t>(m.indices.size()) - m.tubes.all.first;
  close_levels(m.tubes, level, -1);

  // Leaves at the tips of the thinnest twigs: a diamond in the plane of the twig and a side vector,
  // from the tip out along the twig; and for far views the same leaf as one triangle (tree_lod.h),
  // the diamond's half on one side twice as wide: the same reach, area and centre along the twig.
  m.leaves.first = static_cast<std::uint32_t>(m.indices.size());
  std::vector<std::uint32_t> triangles;
  std::vector<std::pair<std::uint32_t, Vec3>> centres;
  double leaf_area = 0.0;
  // The leaves in the segments' order, whose thinnest level is shuffled: the triangles' prefixes are
  // uniform samples of the crown.
  for (std::size_t i : segments) {
    if (t.levels[i] != 1) continue;
    const auto p = static_cast<std::size_t>(t.parents[i]);
    const Vec3 dir = t.vertices[i].position - t.vertices[p].position;
    const float len = tree::length(dir);
    const Vec3 d = dir * (1.0f / len);
    const Vec3 side = perpendicular(d);
    const Vec3 normal = tree::cross(d, side);
    const std::uint32_t shade = hash(static_cast<std::uint32_t>(i)) & 255u;
    const Vec3 along = d * (kLeafLength * len), across = side * (0.5f * kLeafWidth * len);
    m.longest_leaf = std::max(m.longest_leaf, kLeafLength * len);
    leaf_area += 0.5 * kLeafLength * kLeafWidth * len * len;
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (const Vec3 corner : {Vec3{}, along * 0.45f + across, along, along * 0.45f - across * 1.0f, along * 0.45f + across * 2.0f})
      m.vertices.push_back(mesh_vertex(t, i, corner, normal, sh::kTreeMaterialLeaf, shade));
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    triangles.insert(triangles.end(), {base, base + 4, base + 2});
    // The triangle's centre, which the pruning grows it about (tree.vert), packed in its corners'
    // info.w relative to the longest leaf (set below, once known).
    const Vec3 centre = (along + along * 0.45f + across * 2.0f) * (1.0f / 3.0f);
    for (std::uint32_t k = 0; k < 5; ++k) centres.push_back({base + k, centre});
  }
  m.leaves.count = static_cast<std::uint32_t>(m.indices.size()) - m.leaves.first;
  if (m.leaves.count > 0) m.mean_leaf_area = static_cast<float>(leaf_area / (m.leaves.count / 6));
  for (const auto& [vertex, centre] : centres) m.vertices[vertex].info.w = pack_snorm4x8(centre * (1.0f / m.longest_leaf));
  m.leaf_triangles = {static_cast<std::uint32_t>(m.indices.size()), static_cast<std::uint32_t>(triangles.size())};
  m.indices.insert(m.indices.end(), triangles.begin(), triangles.end());

  return m;
}

}  // namespace pond::tree
