#pragma once
// The wind tree's drawable geometry, built once per grown tree on the CPU (no Vulkan): one vertex
// buffer and one index buffer holding three ranges,
//  - lines:  one vertex per skeleton vertex, a line per segment (the article's look);
//  - tubes:  per segment a ring at its base (carrying the parent's wind data) and a ring at its tip
//            (carrying its own), tapered by level, closed into quads;
//  - leaves: one diamond per thinnest twig, hanging off the twig's tip (carrying the tip's data).
// Every vertex is a TreeMeshVertex (shared/tree_render.h): the shader bends its skeleton vertex
// and adds the rest offset, so rings and leaves move with the vertex they belong to.
#include <cstdint>
#include <vector>

#include "shared/tree_render.h"
#include "tree/tree.h"

namespace pond::gpu {

using TreeMeshVertex = shared::tree_wind::TreeMeshVertex;

struct IndexRange {
  std::uint32_t first = 0, count = 0;
};

struct TreeMesh {
  std::vector<TreeMeshVertex> vertices;
  std::vector<std::uint32_t> indices;
  IndexRange lines, tubes, leaves;
  float rest_height = 0.0f;  // highest rest vertex above the root (tree units)
};

// Tube radius at the base of a segment of `level` in a tree of `depth` levels (tree units): the
// trunk's 0.065 of its length, each level 0.62 as thick as the one carrying it. A segment tapers
// to the next level's radius, where its children begin.
float tree_tube_radius(int depth, int level);

TreeMesh build_tree_mesh(const tree::Tree& tree);

}  // namespace pond::gpu
