#pragma once
// The wind tree's drawable geometry, built once per grown tree on the CPU (no Vulkan): one vertex
// buffer and one index buffer holding three ranges,
//  - lines:  one vertex per skeleton vertex, a line per segment (the article's look, and the level
//            of detail's stand-in for twigs thinner than a pixel or so: tree_lod.h);
//  - tubes:  per segment a ring at its base (carrying the parent's wind data) and a ring at its tip
//            (carrying its own), tapered by level, closed into quads wound counter-clockwise seen
//            from outside (the tube pipeline culls back faces);
//  - leaves: one diamond per thinnest twig, hanging off the twig's tip (carrying the tip's data);
//            and the same leaves as one triangle each, for far views (tree_lod.h).
// Every vertex is a TreeMeshVertex (shared/tree_render.h): the shader bends its skeleton vertex
// and adds the rest offset, so rings and leaves move with the vertex they belong to.
//
// Lines and tubes list their segments by level, the trunk first and the thinnest twigs last, so
// that the level of detail draws "every level from L up" as one prefix and "every level below L"
// as one suffix of each range. Within a level, and among the far leaves' triangles, the order is a
// fixed shuffle: any prefix is a uniform sample, which the level of detail's pruning draws
// (tree_lod.h).
#include <cstdint>
#include <vector>

#include "shared/tree_render.h"
#include "tree/tree.h"

namespace pond::tree {

using TreeMeshVertex = shared::tree_wind::TreeMeshVertex;

struct IndexRange {
  std::uint32_t first = 0, count = 0;
};

// An index range whose segments are ordered by level, highest (the trunk) first.
struct LevelRange {
  IndexRange all;
  // level_end[L]: indices (from all.first) of the segments of level >= L, for L in 1 .. depth + 1
  // (level_end[depth + 1] = 0, level_end[1] = all.count); level_end[0] = all.count too.
  std::vector<std::uint32_t> level_end;

  IndexRange at_least(int level) const;  // the segments of level >= `level` (a prefix)
  IndexRange below(int level) const;     // the segments of level < `level` (the rest)
  IndexRange level(int level) const;     // the segments of `level` alone
};

struct TreeMesh {
  std::vector<TreeMeshVertex> vertices;
  std::vector<std::uint32_t> indices;
  LevelRange lines, tubes;
  IndexRange leaves;          // diamonds, two triangles a leaf
  IndexRange leaf_triangles;  // one triangle a leaf: the same length, area and centre along the twig
  float longest_leaf = 0.0f;  // tree units
  float mean_leaf_area = 0.0f;  // tree units^2 (a triangle's, the same as its diamond's)
  // The lines' indices drawn with this vertexOffset reach a second copy of the skeleton's vertices,
  // the twig lines (kTreeMaterialTwig): each carries its segment's direction as its normal and the
  // tube's diameter there in offset.w, which the level of detail's thin lines shade with.
  std::int32_t twig_vertices = 0;
  float rest_height = 0.0f;  // highest rest vertex above the root (tree units)
};

// Tube radius at the base of a segment of `level` in a tree of `depth` levels (tree units): the
// trunk's 0.065 of its length, each level 0.62 as thick as the one carrying it. A segment tapers
// to the next level's radius, where its children begin.
float tree_tube_radius(int depth, int level);

TreeMesh build_tree_mesh(const tree::Tree& tree);

}  // namespace pond::tree
