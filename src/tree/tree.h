#pragma once
// A grown wind tree: the skeleton of SPEC section 2 with everything its vertex shader needs.
// Vertex 0 is the trunk's base (the root); every other vertex is the tip of one segment ("stick")
// from its parent. Vertices are in the article's depth-first order, so a parent always comes
// before its children: one pass in index order visits the tree from the root outward.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tree/vec3.h"

namespace pond::tree {

using TreeVertex = shared::tree_wind::TreeVertex;

inline constexpr int kMinTreeDepth = 1;
inline constexpr int kMaxTreeDepth = 10;  // 29,525 vertices; beyond that a "tree" is a hedge
inline constexpr std::int32_t kNoParent = -1;
inline constexpr std::int8_t kRootLevel = 0;  // the root ends no stick

struct TreeParams {
  int depth = 7;            // recursion levels: 1 = the trunk alone, 7 = the article's Step 1
  std::uint64_t seed = 1;
  float trunk_length = 1.0f;  // the trunk points along +y; the whole tree (and its bending) scales
                              // linearly with this, so 1 is the neutral choice
};

struct Tree {
  int depth = 0;                        // the trunk's level ("meLevels" in the article)
  std::vector<TreeVertex> vertices;     // position, wind vectors X and Z, jitter coefficients
  std::vector<std::int32_t> parents;    // kNoParent for the root
  std::vector<std::int8_t> levels;      // level of the stick ending here: depth for the trunk tip,
                                        // 1 for the thinnest twigs, kRootLevel for the root

  std::size_t size() const { return vertices.size(); }
};

// (3^depth - 1) / 2 sticks plus the root: 1094 at depth 7, 3281 at depth 8.
std::size_t tree_vertex_count(int depth);

// Builds the skeleton, then the wind vectors and the jitter coefficients. Throws InternalError
// (core/errors.h; callers check them first) for a depth outside [kMinTreeDepth, kMaxTreeDepth] or a trunk length that is not positive.
Tree grow_tree(const TreeParams& params);

}  // namespace pond::tree
