#pragma once
// The builder's node-level data, made only where the refinement needs it: per block of
// kBlockCells x kBlockCells cells (aligned like the tiles, neighbours sharing their border nodes),
// the nodes' world positions and budgets in block-local coordinates. Or the whole grid as one
// block, where that costs less (lod_builder.cpp), with its nested error bounds (error_bounds.h) too: there
// triangles of any size are tested on nodes, and the bounds prove large ones without a scan. A
// block's triangles are small enough that scanning them costs less than bounding every node of
// the block (docs/perf.md, "Nested bounds for the whole grid only").
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "lod/camera_budget.h"
#include "lod/error_bounds.h"
#include "lod/grid_hierarchy.h"
#include "core/node_runs.h"
#include "lod/node_positions.h"
#include "lod/tile_ranges.h"
#include "lod/triangle_scan.h"

namespace pond::lod {

// A triangle whose index-space bounding box is at most this many cells across lies in one block
// and is judged on its nodes; one at most twice as wide, on the blocks it covers (wide_leaf.cpp);
// a larger one only on tile ranges (tile_ranges.h). 16 rather than 32: docs/perf.md.
constexpr int kBlockCells = 16;
static_assert(kBlockCells == kTileCells, "a block is a tile's nodes: its tile's range bounds them");
// The block whose cells start at column (or row) k >= 0: unsigned, so the division is a shift.
inline int block_at(int k) { return static_cast<int>(static_cast<unsigned>(k) / kBlockCells); }
// Whether a box of cells is at most a block across (then one block holds its nodes).
inline bool in_one_block(const CellBox& b) { return b.x1 - b.x0 <= kBlockCells && b.y1 - b.y0 <= kBlockCells; }

struct SurfaceBlock {
  Point origin;               // its first node in the grid
  const GridHierarchy* grid;  // its nodes as a grid of their own (for ids and clipping)
  std::vector<float> x, y, z, budget, sure2;  // by local id, kScanOverread past the last node
  std::vector<NestedBound> bounds;  // the whole grid's only: empty in a block
  bool wide = false;  // its budgets and scans may use their AVX2 copies (SurfaceBlocks::begin)

  ScanBudgets scan_budgets() const { return {budget.data(), sure2.data(), wide}; }
  NodePositions positions() const { return soa_positions(x.data(), y.data(), z.data(), grid->rows(), grid->cols()); }
  Tri local(const Tri& t) const {
    const auto at = [&](Point p) { return Point{p.x - origin.x, p.y - origin.y}; };
    return {at(t.apex), at(t.left), at(t.right)};
  }
};

class SurfaceBlocks {
 public:
  SurfaceBlocks(int rows, int cols);

  int blocks_x() const { return blocks_x_; }
  int blocks_y() const { return blocks_y_; }
  // Forgets the last frame's blocks. `terms` are this frame's, of a `largest` bounding every |world
  // coordinate| of `positions`; `ranges` hold them, and `box_budget` is of `terms` (a block inside
  // the frustum gets its budgets without the frustum's tests).
  void begin(const NodePositions& positions, const BudgetTerms& terms, float largest, const TileRanges& ranges,
             const BoxBudget& box_budget);
  // Block (bx, by), made on first use this frame. Throws InputError on a non-finite position in it.
  const SurfaceBlock& block(int bx, int by) {
    const std::size_t k = index(bx, by);
    return made_in_[k] == frame_ ? *pool_[slot_[k]] : make_block(bx, by);
  }
  // The whole grid as one block, made on first use this frame: one pass, no border twice, no
  // per-block set-up, with the grid's nested bounds.
  const SurfaceBlock& whole();
  std::size_t made() const { return used_; }
  // Block (bx, by)'s nodes in the grid.
  core::GridWindow window(int bx, int by) const;
  bool made(int bx, int by) const { return made_in_[index(bx, by)] == frame_; }
  // Made in the frame before this one (frame to frame, the blocks a view needs change little).
  bool made_last_frame(int bx, int by) const { return frame_ > 1 && made_in_[index(bx, by)] == frame_ - 1; }

 private:
  std::size_t index(int bx, int by) const {
    return static_cast<std::size_t>(by) * static_cast<std::size_t>(blocks_x_) + static_cast<std::size_t>(bx);
  }
  const GridHierarchy* shape(int rows, int cols);
  const SurfaceBlock& make_block(int bx, int by);
  void make(SurfaceBlock& b, Point origin, int rows, int cols, bool all_in_view);

  int rows_, cols_, blocks_x_, blocks_y_;
  NodePositions positions_;
  BudgetTerms terms_;
  const TileRanges* ranges_ = nullptr;
  const BoxBudget* box_budget_ = nullptr;
  float largest_ = 0;
  bool wide_ = false;  // the AVX2 copies of the budgets and scans allowed (POND_CPU_FEATURES_MASK)
  std::uint32_t frame_ = 0;
  std::vector<std::uint32_t> made_in_;  // per block: the frame it was made in (0: never)
  std::vector<std::uint32_t> slot_;     // per block: its slot in pool_ when made this frame
  std::vector<std::unique_ptr<SurfaceBlock>> pool_;
  std::size_t used_ = 0;
  SurfaceBlock whole_;
  std::uint32_t whole_made_in_ = 0;
  std::map<std::pair<int, int>, std::unique_ptr<GridHierarchy>> shapes_;
};

}  // namespace pond::lod
