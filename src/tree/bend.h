#pragma once
// The CPU evaluation of the bent tree: the same shared functions the vertex shader calls
// (shaders/shared/tree_wind.h), applied to every vertex. It is the reference the GPU result is
// compared against, and the way to measure how much each bending stretches the branches.
#include <span>
#include <vector>

#include "tree/bend_mode.h"
#include "tree/tree.h"
#include "tree/wind_state.h"

namespace pond::tree {

// Bent positions of all vertices (out.size() == tree.size()) for one frame, in frame.bend_mode:
// - article: p = pos + wX (wind.x + jitter) + wZ (wind.z + jitter) per vertex, independent of the
//   others; branches stretch, by up to sqrt(1 + (s * wind)^2) for a branch with stiffness factor s.
// - keep_length: the article's positions, then walking from the root every segment is rescaled to
//   its rest length and hung from its parent's rescaled tip (tree_wind_keep_length). The shape
//   follows the article's; no segment stretches.
void bend_tree(const Tree& tree, const TreeWindFrame& frame, std::span<Vec3> out);
std::vector<Vec3> bend_tree(const Tree& tree, const TreeWindFrame& frame);

// Rest length of the segment ending at vertex i (i > 0), as both CPU and GPU compute it.
float rest_length(const Tree& tree, std::size_t i);

// Relative length change |bent length / rest length - 1| over all segments.
struct StretchStats {
  double max_relative = 0.0;
  double mean_relative = 0.0;
};
StretchStats measure_stretch(const Tree& tree, std::span<const Vec3> bent);
// Stretch under a steady wind (wind.x, wind.z) with no twig jitter, in the given mode.
StretchStats measure_stretch(const Tree& tree, float wind_x, float wind_z, BendMode mode);

}  // namespace pond::tree
