#pragma once
// The view-dependent LOD builder: (node positions, camera, tau pixels) -> triangle indices into a
// caller's array (the renderer passes its mapped index buffer). Its cost follows what it draws,
// not the grid's size.
//
// The mesh is a conforming longest-edge-bisection mesh (see grid_hierarchy.h). Each frame,
// refinement descends from the roots:
//  1. a triangle stays a leaf when the tile ranges under it (tile_ranges.h) bound its nodes'
//     distance from its interpolation within the least budget of its world box (camera_budget.h:
//     tau * depth / K in the frustum, +infinity for a box wholly outside it): no node is read;
//  2. failing that, a triangle of at most a block (surface_blocks.h) is judged on its block's
//     nodes, made on first use, by an exact scan (triangle_scan.h: a compare a node, then the
//     rows that need it judged closer; where the block is made already, or was the frame before,
//     the scan alone decides: the ranges prove no triangle its nodes do not); one of at most two
//     blocks across, on the blocks it covers, by parts that each lie in one (wide_leaf.cpp).
//     Where the whole grid is read as one block, a triangle of any size is judged there, first on
//     its nested bound (error_bounds.h) and by parts;
//  3. else its midpoint is activated together with its ancestors in the dependency DAG (so the
//     mesh stays conforming), and every triangle created that way is tested in turn, forced ones
//     included. Triangles reaching past the grid (sizes other than 2^k + 1) are tested and drawn
//     as their clipped fans, exactly, and dropped when wholly outside;
//  4. the leaves are written depth first, which walks a Sierpinski curve (vertex-cache friendly).
// Where not every node is on the host (NodePositions::fetch), a triangle whose block is not waits
// while the rest refine; the blocks they wait for are then brought at once, and so on, and last
// the leaves' corners. A triangle's test does not depend on what was made before it, so the mesh
// is the same as with every node at hand.
// Every leaf passed a test, and every left-out node lies in leaves only (no T-junctions), so
// every left-out node in the frustum is within tau pixels: a strict bound, not a heuristic.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "lod/camera_budget.h"
#include "lod/error_bounds.h"
#include "lod/grid_hierarchy.h"
#include "lod/node_positions.h"
#include "lod/surface_blocks.h"
#include "lod/tile_ranges.h"

namespace pond::lod {

struct BuildStats {
  std::size_t triangles = 0;
  std::size_t tested = 0;        // candidate leaves tested
  std::size_t ranged = 0;        // accepted by the tile ranges (no node read)
  std::size_t blocks = 0;        // blocks of nodes read (surface_blocks.h)
  bool whole = false;            // the whole grid read as one block instead
  std::size_t proved = 0;        // accepted by the whole grid's nested bounds alone (0 with blocks)
  std::size_t scanned = 0;       // needed an exact scan
  long long scanned_nodes = 0;   // nodes visited by exact scans
  std::size_t brought = 0;       // times nodes were brought to the host (NodePositions::fetch)
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
  // number of indices written. `ranges` are those of `positions` (a solver's tile bounds, or
  // tile_ranges(positions)). Throws InputError on a bad camera or tolerance or a non-finite
  // position it reads, and InternalError for positions or ranges of another grid or an `out`
  // shorter than max_indices().
  std::size_t build(const NodePositions& positions, const TileRanges& ranges, const Camera& camera,
                    double tolerance_px, std::span<std::uint32_t> out);
  // The same, computing the ranges from the positions first (O(nodes)).
  std::size_t build(const NodePositions& positions, const Camera& camera, double tolerance_px,
                    std::span<std::uint32_t> out);

  const BuildStats& stats() const { return stats_; }
  // The world positions of the vertices of the last build()'s triangles, by node index
  // (row * cols + col); other entries are stale.
  std::span<const float> world_x() const { return world_[0]; }
  std::span<const float> world_y() const { return world_[1]; }
  std::span<const float> world_z() const { return world_[2]; }
  const GridHierarchy& grid() const { return grid_; }
  // The nodes the last build read, as windows (its blocks, and its leaves' corners outside them):
  // what a solver reading back in parts keeps on the host for the next build, since frame to frame
  // they change little. nullopt: the whole grid (the next build reads all of it).
  const std::optional<std::vector<core::GridWindow>>& reads() const { return reads_; }

 private:
  enum class Fit { yes, no, later };  // later: its block is not on the host yet
  Fit leaf_fits(const Tri& t, Point m);
  [[gnu::noinline]] Fit any_leaf_fits(const Tri& t, Point m);
  Fit wide_leaf_fits(const Tri& t, Point m);  // wide_leaf.cpp
  double deviation_up(double d2) const;
  bool block_held(int bx, int by, bool ask = true);
  std::uint8_t& held_at(int bx, int by) {
    return held_[static_cast<std::size_t>(by) * static_cast<std::size_t>(blocks_.blocks_x()) + static_cast<std::size_t>(bx)];
  }
  void refine();
  void read_corners(std::span<const std::uint32_t> triangles);
  bool in_a_block(int row, int col, bool or_queued);
  void note_corners(std::span<const Point> corners);
  bool leaf_is_fine(const SurfaceBlock& b, const Tri& t, Point m);
  bool nested_leaf_is_fine(const SurfaceBlock& b, const Tri& t, Point m);  // nested_leaf.cpp
  bool clipped_leaf_is_fine(const SurfaceBlock& b, const GridPolygon& polygon);
  void activate(Point v, Point expanding = {-1, -1});
  void mark(std::uint8_t& s, std::uint8_t bits, Point v);
  void emit(const Tri& t, bool enter_left, std::uint32_t*& out);
  void emit_split(const Tri& t, Point m, bool enter_left, std::uint32_t*& out);
  void emit_leaf(const Tri& t, std::uint32_t*& out);
  [[gnu::noinline]] void emit_fan(const Tri& t, std::uint32_t*& out);
  std::span<const std::uint32_t> drawn_vertices();
  std::size_t blocks_needed(std::span<const std::uint32_t> triangles, std::size_t enough);

  GridHierarchy grid_;
  SurfaceBlocks blocks_;
  const TileRanges* ranges_ = nullptr;  // this frame's
  NodePositions positions_;             // this frame's
  std::optional<BoxBudget> box_budget_;  // this frame's
  float largest_ = 0;  // this frame's bound on every |coordinate|
  std::vector<float> x_, y_, z_;  // the drawn vertices' world positions (read in blocks)
  std::span<const float> world_[3];  // those, or the whole grid's when it was read whole
  std::vector<std::uint8_t> state_;  // per domain node: kActive | kExpanded* bits
  std::vector<std::uint32_t> marked_;  // the domain ids whose state this frame set
  std::vector<std::uint32_t> fan_corners_, drawn_;  // emit()'s clipped fans' corners; drawn_vertices()
  std::vector<Tri> work_;
  bool whole_ = false;                // this frame reads the whole grid (see build())
  std::vector<std::uint8_t> needed_;  // blocks_needed()'s scratch
  // With NodePositions::fetch: per block, this frame, 0 not asked, 1 held, 2 to bring; the windows
  // to bring, the triangles waiting for them, and the windows read, for reads().
  std::vector<std::uint8_t> held_;
  std::vector<core::GridWindow> to_bring_;
  std::vector<Tri> waiting_;
  // Node ids: the corners of leaves the ranges accepted since the last round (note_corners()), and
  // those brought with blocks this frame.
  std::vector<std::uint32_t> ranged_corners_, corners_brought_;
  std::optional<std::vector<core::GridWindow>> reads_;
  BuildStats stats_;
};

}  // namespace pond::lod
