#include "tree/tree.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/errors.h"
#include "tree/jitter_coefficients.h"
#include "tree/skeleton.h"
#include "tree/wind_vectors.h"

namespace pond::tree {

std::size_t tree_vertex_count(int depth) {
  std::size_t sticks = 0, per_level = 1;
  for (int level = 0; level < depth; ++level, per_level *= 3) sticks += per_level;
  return sticks + 1;
}

Tree grow_tree(const TreeParams& params) {
  if (params.depth < kMinTreeDepth || params.depth > kMaxTreeDepth)
    throw InternalError("tree depth " + std::to_string(params.depth) + " is outside " +
                                std::to_string(kMinTreeDepth) + ".." + std::to_string(kMaxTreeDepth));
  if (!(params.trunk_length > 0.0f) || !std::isfinite(params.trunk_length))
    throw InternalError("tree trunk length must be positive and finite");
  Tree tree;
  build_skeleton(params, tree);
  compute_wind_vectors(tree);
  draw_jitter_coefficients(tree, params.seed);
  return tree;
}

}  // namespace pond::tree
