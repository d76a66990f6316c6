#include "lod/surface_blocks.h"

#include <algorithm>

#include "core/cpu_features.h"
#include "lod/position_copy.h"
#include "lod/triangle_scan.h"

namespace pond::lod {
namespace {

int blocks_on(int nodes) { return (nodes - 2) / kBlockCells + 1; }

}  // namespace

SurfaceBlocks::SurfaceBlocks(int rows, int cols)
    : rows_(rows), cols_(cols), blocks_x_(blocks_on(cols)), blocks_y_(blocks_on(rows)) {
  const std::size_t blocks = static_cast<std::size_t>(blocks_x_) * static_cast<std::size_t>(blocks_y_);
  made_in_.assign(blocks, 0);
  slot_.assign(blocks, 0);
}

void SurfaceBlocks::begin(const NodePositions& positions, const BudgetTerms& terms, float largest,
                          const TileRanges& ranges, const BoxBudget& box_budget) {
  positions_ = positions, terms_ = terms, largest_ = largest;
  ranges_ = &ranges, box_budget_ = &box_budget;
  // Once a frame: cpu_has reads the environment. The copies exist where this build has node_budgets'.
  wide_ = core::cpu_has(core::CpuFeature::avx2) && wide_budgets_available();
  used_ = 0;
  if (++frame_ == 0) {  // after 2^32 frames: every stamp would look current
    std::fill(made_in_.begin(), made_in_.end(), 0u);
    whole_made_in_ = 0;
    frame_ = 1;
  }
}

const GridHierarchy* SurfaceBlocks::shape(int rows, int cols) {
  auto& g = shapes_[{rows, cols}];
  if (!g) g = std::make_unique<GridHierarchy>(rows, cols);
  return g.get();
}

const SurfaceBlock& SurfaceBlocks::make_block(int bx, int by) {
  const std::size_t k = index(bx, by);
  if (used_ == pool_.size()) pool_.push_back(std::make_unique<SurfaceBlock>());
  SurfaceBlock& b = *pool_[used_];
  const core::GridWindow w = window(bx, by);
  // A block is its tile's nodes: its world box is theirs.
  const TileRanges::WorldBox box =
      ranges_->world_box(w.col0, w.col0 + w.cols - 1, w.row0, w.row0 + w.rows - 1, ranges_->cell(0, bx, by));
  make(b, {w.col0, w.row0}, w.rows, w.cols, box_budget_->inside(box.lo, box.hi));
  made_in_[k] = frame_;
  slot_[k] = static_cast<std::uint32_t>(used_++);
  return b;
}

core::GridWindow SurfaceBlocks::window(int bx, int by) const {
  const int row0 = by * kBlockCells, col0 = bx * kBlockCells;
  return {row0, col0, std::min(kBlockCells + 1, rows_ - row0), std::min(kBlockCells + 1, cols_ - col0)};
}

const SurfaceBlock& SurfaceBlocks::whole() {
  if (whole_made_in_ != frame_) {
    make(whole_, {0, 0}, rows_, cols_, false);
    // The vertices nested_bounds() leaves alone depend on the grid's shape only: set them once.
    if (whole_.bounds.empty()) whole_.bounds.assign(static_cast<std::size_t>(rows_) * static_cast<std::size_t>(cols_), kNothingProved);
    nested_bounds(*whole_.grid, whole_.positions(), largest_, whole_.budget.data(), whole_.bounds.data());
  }
  whole_made_in_ = frame_;
  return whole_;
}

void SurfaceBlocks::make(SurfaceBlock& b, Point origin, int rows, int cols, bool all_in_view) {
  b.origin = origin;
  b.grid = shape(rows, cols);
  const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  for (std::vector<float>* v : {&b.x, &b.y, &b.z, &b.budget, &b.sure2}) v->resize(n + kScanOverread);
  copy_finite_block(positions_, b.origin.y, b.origin.x, rows, cols, b.x.data(), b.y.data(), b.z.data(), wide_);
  b.wide = wide_;
  node_budgets(b.positions(), terms_, b.budget.data(), wide_, all_in_view);
  scan_thresholds(b.budget.data(), n, largest_, b.sure2.data(), wide_);
}

}  // namespace pond::lod
