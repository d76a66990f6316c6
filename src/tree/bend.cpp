#include "tree/bend.h"

#include <cmath>

#include "core/errors.h"

namespace pond::tree {
namespace sh = shared::tree_wind;

namespace {
void bend_article(const Tree& tree, const TreeWindFrame& frame, std::span<Vec3> out) {
  const Vec3 q{frame.twig.x, frame.twig.y, frame.twig.z};
  for (std::size_t i = 0; i < tree.size(); ++i) {
    const TreeVertex& v = tree.vertices[i];
    out[i] = sh::tree_wind_bend(v.position, v.wind_x, v.wind_z, v.jitter, frame.wind.x,
                                frame.wind.z, q);
  }
}
}  // namespace

float rest_length(const Tree& tree, std::size_t i) {
  const auto p = static_cast<std::size_t>(tree.parents[i]);
  return sh::tree_wind_rest_length(tree.vertices[p].position, tree.vertices[i].position);
}

void bend_tree(const Tree& tree, const TreeWindFrame& frame, std::span<Vec3> out) {
  if (out.size() != tree.size()) throw InternalError("bend_tree: output size mismatch");
  bend_article(tree, frame, out);
  if (frame.bend_mode != sh::kTreeBendKeepLength) return;
  // Walk from the root outward (parents precede children). out[p] is overwritten with p's kept
  // position before p's children are reached, and they still need p's article position: so the
  // article pass is kept in a copy.
  const std::vector<Vec3> article(out.begin(), out.end());
  for (std::size_t i = 0; i < tree.size(); ++i) {
    const std::int32_t p = tree.parents[i];
    if (p == kNoParent) continue;
    const auto pi = static_cast<std::size_t>(p);
    out[i] = sh::tree_wind_keep_length(out[pi], article[pi], article[i], rest_length(tree, i));
  }
}

std::vector<Vec3> bend_tree(const Tree& tree, const TreeWindFrame& frame) {
  std::vector<Vec3> out(tree.size());
  bend_tree(tree, frame, out);
  return out;
}

StretchStats measure_stretch(const Tree& tree, std::span<const Vec3> bent) {
  StretchStats s;
  std::size_t segments = 0;
  for (std::size_t i = 0; i < tree.size(); ++i) {
    const std::int32_t p = tree.parents[i];
    if (p == kNoParent) continue;
    const auto pi = static_cast<std::size_t>(p);
    // In double, so the measurement adds no rounding of its own to what it measures.
    auto len = [](Vec3 a, Vec3 b) {
      const double dx = double(b.x) - a.x, dy = double(b.y) - a.y, dz = double(b.z) - a.z;
      return std::sqrt(dx * dx + dy * dy + dz * dz);
    };
    const double rest = len(tree.vertices[pi].position, tree.vertices[i].position);
    const double change = std::abs(len(bent[pi], bent[i]) / rest - 1.0);
    s.max_relative = std::max(s.max_relative, change);
    s.mean_relative += change;
    ++segments;
  }
  if (segments) s.mean_relative /= static_cast<double>(segments);
  return s;
}

StretchStats measure_stretch(const Tree& tree, float wind_x, float wind_z, BendMode mode) {
  TreeWindFrame frame{};
  frame.wind = {wind_x, 0.0f, wind_z, 0.0f};
  frame.bend_mode = static_cast<std::uint32_t>(mode);
  return measure_stretch(tree, bend_tree(tree, frame));
}

}  // namespace pond::tree
