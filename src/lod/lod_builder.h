#pragma once
// The view-dependent LOD builder: (node positions, camera, tau pixels) -> triangle indices into a
// caller's array (the renderer passes its mapped index buffer).
//
// The mesh is a conforming longest-edge-bisection mesh (see grid_hierarchy.h). Each frame:
//  1. every node gets a budget: tau * depth / K inside the frustum, +infinity outside;
//  2. nested error bounds are computed bottom-up (error_bounds.h), O(nodes);
//  3. refinement from the roots: a triangle stays a leaf when its nested bound proves every node
//     in it is within budget, or, failing that, when an exact scan of its nodes shows it; else its
//     midpoint is activated together with its ancestors in the dependency DAG (so the mesh stays
//     conforming), and every triangle created that way is tested in turn, forced ones included;
//     Triangles reaching past the grid (sizes other than 2^k + 1) are tested and drawn as their
//     clipped fans, exactly (triangle_scan.h), and dropped when wholly outside;
//  4. the leaves are written depth first, which walks a Sierpinski curve (vertex-cache friendly).
// Every leaf passed the test, and every left-out node lies in leaves only (no T-junctions), so
// every left-out node in the frustum is within tau pixels: a strict bound, not a heuristic.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "lod/camera_budget.h"
#include "lod/error_bounds.h"
#include "lod/grid_hierarchy.h"
#include "lod/node_positions.h"

namespace pond::lod {

struct BuildStats {
  std::size_t triangles = 0;
  std::size_t tested = 0;        // candidate leaves tested
  std::size_t proved = 0;        // accepted by the nested bound alone
  std::size_t scanned = 0;       // needed an exact scan
  long long scanned_nodes = 0;   // nodes visited by exact scans
};

class LodBuilder {
 public:
  LodBuilder(int rows, int cols);

  int rows() const { return grid_.rows(); }
  int cols() const { return grid_.cols(); }
  // The most indices build() can write: the full mesh, 6 (rows-1)(cols-1).
  std::size_t max_indices() const;
  std::size_t full_triangles() const { return max_indices() / 3; }

  // Writes the triangles (3 indices each, node index = row * cols + col) to `out` and returns the
  // number of indices written. Throws InputError on a bad camera or tolerance or a non-finite position, and
  // InternalError for positions of another grid or an `out` shorter than max_indices().
  std::size_t build(const NodePositions& positions, const Camera& camera, double tolerance_px,
                    std::span<std::uint32_t> out);

  const BuildStats& stats() const { return stats_; }
  // The world positions the last build() read, by node index (row * cols + col).
  std::span<const float> world_x() const { return x_; }
  std::span<const float> world_y() const { return y_; }
  std::span<const float> world_z() const { return z_; }
  const GridHierarchy& grid() const { return grid_; }

 private:
  bool leaf_is_fine(const Tri& t, std::uint32_t mid);
  bool clipped_leaf_is_fine(const GridPolygon& polygon);
  void activate(Point v);
  void emit(const Tri& t, bool enter_left, std::uint32_t*& out) const;

  GridHierarchy grid_;
  std::vector<float> x_, y_, z_;  // this frame's positions, structure of arrays
  float largest_ = 0;  // this frame's largest |coordinate|
  std::vector<float> budget_;
  std::vector<NestedBound> bounds_;
  std::vector<std::uint8_t> state_;  // per domain node: kActive | kExpanded* bits
  std::vector<Tri> work_;
  BuildStats stats_;
};

}  // namespace pond::lod
