#include "lod/lod_builder.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/errors.h"
#include "lod/position_copy.h"
#include "lod/range_proof.h"
#include "lod/surface_blocks.h"
#include "lod/triangle_scan.h"

namespace pond::lod {
namespace {

constexpr std::uint8_t kActive = 1;
// Each split vertex has up to two triangles (one per side of its hypotenuse); these bits say
// their children were already queued, so no triangle is expanded twice.
constexpr std::uint8_t kExpanded[2] = {2, 4};

// Which side of its diamond's hypotenuse a triangle lies on, from its apex.
int side_of(const Tri& t, Point m) {
  return t.apex.y > m.y || (t.apex.y == m.y && t.apex.x > m.x) ? 1 : 0;
}

}  // namespace

LodBuilder::LodBuilder(int rows, int cols) : grid_(rows, cols), blocks_(rows, cols) {
  const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  x_.resize(n), y_.resize(n), z_.resize(n);
  state_.assign(grid_.domain_nodes(), 0);
  for (std::uint32_t id : grid_.always_split_ids()) state_[id] = kActive;
}

std::size_t LodBuilder::max_indices() const {
  return 6 * static_cast<std::size_t>(rows() - 1) * static_cast<std::size_t>(cols() - 1);
}

// Is t, a triangle of the hierarchy whose midpoint m is not active, fine as a leaf, on the tile
// ranges or (a triangle within a block) its block's nodes? Later: its block is not on the host yet.
// Most tests are of a small triangle within the grid whose block is made: that case first, in a
// few lines that save few registers, the others in any_leaf_fits() (which decides it the same way).
LodBuilder::Fit LodBuilder::leaf_fits(const Tri& t, Point m) {
  if (!whole_ && grid_.hierarchy_tri_within_grid(t)) {
    const CellBox box = box_of(t);
    const int bx = block_at(box.x0), by = block_at(box.y0);
    if (in_one_block(box) && blocks_.made(bx, by)) {
      ++stats_.tested;
      const SurfaceBlock& b = blocks_.block(bx, by);
      return leaf_is_fine(b, b.local(t), {m.x - b.origin.x, m.y - b.origin.y}) ? Fit::yes : Fit::no;
    }
  }
  return any_leaf_fits(t, m);
}

LodBuilder::Fit LodBuilder::any_leaf_fits(const Tri& t, Point m) {
  const CellBox box = box_of(t);  // named, not bound: clang 14 cannot capture bindings in lambdas
  const int x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
  const bool inside = grid_.hierarchy_tri_within_grid(t);
  GridPolygon clipped;  // t's part in the grid, when it reaches past it
  if (!inside && (clipped = clip_to_grid(t, rows(), cols())).count < 3) return Fit::yes;  // wholly outside
  const auto fit = [](bool fine) { return fine ? Fit::yes : Fit::no; };
  ++stats_.tested;
  if (whole_) {
    const SurfaceBlock& w = blocks_.whole();
    return fit(inside ? leaf_is_fine(w, t, m) : clipped_leaf_is_fine(w, clipped));
  }
  const bool small = in_one_block(box);
  const bool wide = !small && inside && x1 - x0 <= 2 * kBlockCells && y1 - y0 <= 2 * kBlockCells;
  const int bx = block_at(x0), by = block_at(y0);  // the corners are in the domain: x0, y0 >= 0
  // Fine when the ranges prove it or (a small triangle) its block's nodes do. The ranges prove no
  // triangle its nodes do not (camera_budget.h: BoxBudget's budgets are at most the nodes'), so
  // where the block is made already its nodes alone decide, and else the ranges are tried first:
  // the outcome is the same, so the mesh does not depend on which blocks were made or brought before.
  const auto ranged = [&] {
    const Point own[3] = {t.apex, t.left, t.right};
    const std::span<const Point> corners = inside ? std::span<const Point>(own) : clipped.corners();
    const bool fine = RangeProof(*ranges_, *box_budget_).proves(x0, std::min(x1, cols() - 1), y0, std::min(y1, rows() - 1), corners);
    stats_.ranged += fine;
    if (fine) note_corners(corners);
    return fine;
  };
  const auto on_nodes = [&] {
    const SurfaceBlock& b = blocks_.block(bx, by);
    const Tri local = b.local(t);
    if (inside) return leaf_is_fine(b, local, {m.x - b.origin.x, m.y - b.origin.y});
    return clipped_leaf_is_fine(b, clip_to_grid(local, b.grid->rows(), b.grid->cols()));
  };
  // A block made last frame is likely needed again: its nodes first then too, not a ranged test
  // that would most likely fail (where the host holds it already: no wait is added for it).
  if (small && (blocks_.made(bx, by) || (blocks_.made_last_frame(bx, by) && block_held(bx, by, false))))
    return fit(on_nodes());
  if (ranged()) return Fit::yes;
  if (wide) return wide_leaf_fits(t, m);
  if (!small) return Fit::no;
  if (!block_held(bx, by)) {
    --stats_.tested;  // tested again once its block is brought
    return Fit::later;
  }
  return fit(on_nodes());
}

// Whether block (bx, by)'s nodes are on the host; when not and `ask`, it is queued to be brought.
bool LodBuilder::block_held(int bx, int by, bool ask) {
  if (!positions_.fetch) return true;
  std::uint8_t& h = held_at(bx, by);
  if (h == 0) {
    const core::GridWindow w = blocks_.window(bx, by);
    if (positions_.fetch->holds(w)) h = 1;
    else if (ask) h = 2, to_bring_.push_back(w);
  }
  return h == 1;
}

bool LodBuilder::leaf_is_fine(const SurfaceBlock& blk, const Tri& t, Point mid_point) {
  if (!blk.bounds.empty()) return nested_leaf_is_fine(blk, t, mid_point);
  // A block's triangle is scanned whole, at once: with a compare a node, the scan's first rows cost
  // less than quick rejects at its edges' midpoints (docs/perf.md, "A block's triangle scanned at once").
  ++stats_.scanned;
  return within_budget(*blk.grid, blk.positions(), blk.scan_budgets(), largest_, t, &stats_.scanned_nodes);
}

bool LodBuilder::clipped_leaf_is_fine(const SurfaceBlock& b, const GridPolygon& polygon) {
  ++stats_.scanned;
  return fan_within_budget(polygon, b.positions(), b.budget.data(), &stats_.scanned_nodes);
}

// Sets bits of v's state, remembering v so that the next build clears it.
void LodBuilder::mark(std::uint8_t& s, std::uint8_t bits, Point v) {
  if (s == 0) marked_.push_back(grid_.domain_id(v));
  s |= bits;
}

// Activates v and, first, its parents (the dependency closure that keeps the mesh conforming),
// then queues the triangles of v's diamond so that their new children get tested, but for the one
// with apex `expanding` (refine() expands it at once).
void LodBuilder::activate(Point v, Point expanding) {
  std::uint8_t& s = state_[grid_.domain_id(v)];
  if (s & kActive) return;
  mark(s, kActive, v);
  const Diamond d = GridHierarchy::diamond(v);
  for (Point p : d.parents)
    if (grid_.in_domain(p)) activate(p);
  for (Point p : d.parents)
    if (grid_.in_domain(p) && p != expanding) work_.push_back(oriented(p, d.end0, d.end1));
}

std::size_t LodBuilder::build(const NodePositions& p, const Camera& camera, double tolerance_px,
                              std::span<std::uint32_t> out) {
  validate(camera, tolerance_px);  // a bad camera before reading every node
  return build(p, tile_ranges(p), camera, tolerance_px, out);
}

std::size_t LodBuilder::build(const NodePositions& p, const TileRanges& ranges, const Camera& camera,
                              double tolerance_px, std::span<std::uint32_t> out) {
  validate(camera, tolerance_px);
  if (p.rows != rows() || p.cols != cols())
    throw InternalError("positions are " + std::to_string(p.rows) + " x " + std::to_string(p.cols) +
                     " but the LOD builder was made for " + std::to_string(rows()) + " x " +
                     std::to_string(cols()));
  if (ranges.rows() != rows() || ranges.cols() != cols())
    throw InternalError("tile ranges are of a " + std::to_string(ranges.rows()) + " x " +
                        std::to_string(ranges.cols()) + " grid, the LOD builder's is " + std::to_string(rows()) +
                        " x " + std::to_string(cols()));
  if (out.size() < max_indices())
    throw InternalError("LOD index array holds " + std::to_string(out.size()) +
                            " indices, needs " + std::to_string(max_indices()));
  stats_ = {};
  ranges_ = &ranges;
  positions_ = p;
  largest_ = ranges.largest();
  const BudgetTerms terms = budget_terms(camera, tolerance_px, largest_);
  box_budget_.emplace(terms);
  blocks_.begin(p, terms, largest_, ranges, *box_budget_);

  for (std::uint32_t id : marked_) state_[id] = 0;
  marked_.clear();
  for (std::uint32_t id : grid_.always_split_ids()) state_[id] = kActive;
  if (whole_ && p.fetch) {
    const core::GridWindow all{0, 0, rows(), cols()};
    if (!p.fetch->holds(all)) p.fetch->bring_and_wait(std::span(&all, 1)), ++stats_.brought;
  }
  ranged_corners_.clear(), corners_brought_.clear();
  if (p.fetch) held_.assign(static_cast<std::size_t>(blocks_.blocks_x()) * static_cast<std::size_t>(blocks_.blocks_y()), 0);
  work_.assign(grid_.roots().begin(), grid_.roots().end());
  refine();

  fan_corners_.clear();
  std::uint32_t* cursor = out.data();
  for (const Tri& root : grid_.roots()) emit(root, true, cursor);
  const std::size_t written = static_cast<std::size_t>(cursor - out.data());
  stats_.triangles = written / 3;
  stats_.blocks = blocks_.made();
  stats_.whole = whole_;
  if (whole_) {
    reads_.reset();
    const SurfaceBlock& w = blocks_.whole();
    world_[0] = std::span(w.x).first(p.nodes()), world_[1] = std::span(w.y).first(p.nodes());
    world_[2] = std::span(w.z).first(p.nodes());
  } else {
    read_corners(out.first(written));
    copy_nodes(p, drawn_vertices(), x_.data(), y_.data(), z_.data());
    world_[0] = x_, world_[1] = y_, world_[2] = z_;
  }
  // Frame to frame the view and the water change little, so this frame's counts choose how the
  // next one reads its nodes: the whole grid in one pass, whose nested bounds prove most large
  // triangles without a scan, or blocks, whose triangles are scanned. Costs in units of the whole
  // pass's per node (docs/perf.md, "Blocks or the whole grid"): a block made, and the scans a tested
  // triangle needs in blocks beyond those of the whole grid. The whole grid when the blocks this
  // frame needed (made, or where it was read whole, holding a drawn small triangle) cost more.
  constexpr double kBlockCost = 113, kTestCost = 4.5;
  const double spare = static_cast<double>(p.nodes()) - kTestCost * static_cast<double>(stats_.tested);
  const std::size_t enough = spare < 0 ? 0 : static_cast<std::size_t>(spare / kBlockCost) + 1;  // blocks
  whole_ = enough == 0 || (whole_ ? blocks_needed(out.first(written), enough) : blocks_.made()) >= enough;
  if (whole_) reads_.reset();
  return written;
}

// Descends from work_ until every queued triangle is a leaf or split. Triangles waiting for their
// block (leaf_fits() later) go on once the blocks are brought, all at once.
void LodBuilder::refine() {
  for (;;) {
    while (!work_.empty()) {
      const Tri t = work_.back();
      work_.pop_back();
      Point m;
      if (!midpoint(t, m)) continue;  // a half cell: no node inside
      std::uint8_t& s = state_[grid_.domain_id(m)];
      if (!(s & kActive)) {
        const Fit fit = leaf_fits(t, m);
        if (fit == Fit::later) waiting_.push_back(t);
        if (fit != Fit::no) continue;
        activate(m, t.apex);  // queues its neighbour across the hypotenuse; t is expanded below
      }
      const std::uint8_t bit = kExpanded[side_of(t, m)];
      if (s & bit) continue;
      mark(s, bit, m);
      work_.push_back(child_left(t, m));
      work_.push_back(child_right(t, m));
    }
    if (waiting_.empty()) return;
    // The blocks and, in the same copy, the corners of the leaves the ranges accepted so far that no
    // block asked for holds: read_corners() would otherwise bring them in a wait of their own.
    const std::size_t blocks = to_bring_.size();
    const std::uint32_t c = static_cast<std::uint32_t>(cols());
    for (std::uint32_t id : ranged_corners_) {
      const int row = static_cast<int>(id / c), col = static_cast<int>(id % c);
      if (in_a_block(row, col, true)) continue;
      to_bring_.push_back({row, col, 1, 1});
      corners_brought_.push_back(id);
    }
    ranged_corners_.clear();
    positions_.fetch->bring_and_wait(to_bring_);
    ++stats_.brought;
    for (std::size_t k = 0; k < blocks; ++k) held_at(to_bring_[k].col0 / kBlockCells, to_bring_[k].row0 / kBlockCells) = 1;
    to_bring_.clear();
    work_.swap(waiting_);
  }
}

// With NodePositions::fetch: brings the leaves' corners the host lacks (those outside the blocks
// read), and sets reads() to the blocks asked for and those corners.
void LodBuilder::read_corners(std::span<const std::uint32_t> triangles) {
  if (!positions_.fetch) return;
  std::vector<core::GridWindow> reads;  // the blocks asked for: made, or brought and then not needed
  for (int by = 0; by < blocks_.blocks_y(); ++by)
    for (int bx = 0; bx < blocks_.blocks_x(); ++bx)
      if (held_at(bx, by) == 1) reads.push_back(blocks_.window(bx, by));
  const std::size_t blocks = reads.size();
  const std::uint32_t c = static_cast<std::uint32_t>(cols());
  std::vector<std::uint32_t> outside;  // the leaves' corners, and those brought with blocks (read too)
  for (std::span<const std::uint32_t> ids : {triangles, std::span<const std::uint32_t>(corners_brought_)})
    for (std::uint32_t id : ids)
      if (!in_a_block(static_cast<int>(id / c), static_cast<int>(id % c), false)) outside.push_back(id);
  std::sort(outside.begin(), outside.end());
  outside.erase(std::unique(outside.begin(), outside.end()), outside.end());
  for (std::uint32_t id : outside) reads.push_back({static_cast<int>(id / c), static_cast<int>(id % c), 1, 1});
  std::vector<core::GridWindow> missing;
  for (std::size_t k = blocks; k < reads.size(); ++k)
    if (!positions_.fetch->holds(reads[k])) missing.push_back(reads[k]);
  if (!missing.empty()) positions_.fetch->bring_and_wait(missing), ++stats_.brought;
  reads_ = std::move(reads);
}

// Whether node (row, col) lies in a block held this frame or, with `or_queued`, about to be brought.
bool LodBuilder::in_a_block(int row, int col, bool or_queued) {
  for (int by : {(row - 1) / kBlockCells, row / kBlockCells})
    for (int bx : {(col - 1) / kBlockCells, col / kBlockCells}) {
      if (bx < 0 || by < 0 || bx >= blocks_.blocks_x() || by >= blocks_.blocks_y()) continue;
      const std::uint8_t h = held_at(bx, by);
      if (h == 1 || (or_queued && h == 2)) return true;
    }
  return false;
}

// With NodePositions::fetch: a leaf accepted on the ranges; its corners are read at the end.
void LodBuilder::note_corners(std::span<const Point> corners) {
  if (!positions_.fetch) return;
  for (const Point& p : corners) ranged_corners_.push_back(grid_.id(p));
}

// The blocks holding a triangle of `triangles` small enough to lie in one (those the block path
// would have made at least), counted up to `enough`.
std::size_t LodBuilder::blocks_needed(std::span<const std::uint32_t> triangles, std::size_t enough) {
  needed_.assign(static_cast<std::size_t>(blocks_.blocks_x()) * static_cast<std::size_t>(blocks_.blocks_y()), 0);
  std::size_t count = 0;
  const std::uint32_t c = static_cast<std::uint32_t>(cols());
  for (std::size_t k = 0; k + 2 < triangles.size(); k += 3) {
    const std::uint32_t a = triangles[k], b = triangles[k + 1], d = triangles[k + 2];
    const int x0 = static_cast<int>(std::min({a % c, b % c, d % c})), x1 = static_cast<int>(std::max({a % c, b % c, d % c}));
    const int y0 = static_cast<int>(std::min({a / c, b / c, d / c})), y1 = static_cast<int>(std::max({a / c, b / c, d / c}));
    if (x1 - x0 > kBlockCells || y1 - y0 > kBlockCells) continue;
    std::uint8_t& seen = needed_[static_cast<std::size_t>(y0 / kBlockCells) * static_cast<std::size_t>(blocks_.blocks_x()) +
                                 static_cast<std::size_t>(x0 / kBlockCells)];
    count += seen == 0;
    seen = 1;
    if (count == enough) break;
  }
  return count;
}

// The grid ids of the leaves' corners: the active vertices in the grid (every one is a corner of a
// leaf, and every leaf's corner is one, or a root's), and the corners of the clipped fans.
std::span<const std::uint32_t> LodBuilder::drawn_vertices() {
  drawn_.clear();
  const auto add = [&](std::uint32_t d) {
    const Point v = grid_.domain_point(d);
    if (grid_.inside(v)) drawn_.push_back(grid_.id(v));
  };
  for (std::uint32_t d : marked_) add(d);
  for (std::uint32_t d : grid_.always_split_ids()) add(d);
  drawn_.insert(drawn_.end(), fan_corners_.begin(), fan_corners_.end());
  return drawn_;
}

// Depth first; entering each triangle at the hypotenuse end the previous one left at, the leaves
// form a Sierpinski curve, so consecutive triangles share vertices.
void LodBuilder::emit(const Tri& t, bool enter_left, std::uint32_t*& out) {
  Point m;
  if (midpoint(t, m) && (state_[grid_.domain_id(m)] & kActive)) emit_split(t, m, enter_left, out);
  else emit_leaf(t, out);
}

// The children of t, split at m, in emit()'s order: a leaf child written here, so the recursion
// calls only for triangles that split again.
void LodBuilder::emit_split(const Tri& t, Point m, bool enter_left, std::uint32_t*& out) {
  const Tri children[2] = {enter_left ? child_left(t, m) : child_right(t, m), enter_left ? child_right(t, m) : child_left(t, m)};
  for (const Tri& c : children) {
    Point cm;
    if (midpoint(c, cm) && (state_[grid_.domain_id(cm)] & kActive)) emit_split(c, cm, !enter_left, out);
    else emit_leaf(c, out);
  }
}

void LodBuilder::emit_leaf(const Tri& t, std::uint32_t*& out) {
  if (grid_.hierarchy_tri_within_grid(t)) {
    *out++ = grid_.id(t.apex);
    *out++ = grid_.id(t.left);
    *out++ = grid_.id(t.right);
    return;
  }
  emit_fan(t, out);
}

// A leaf reaching past the grid: its part in the grid as a fan, none when it lies outside. Out of
// line, so that emit()'s recursion keeps a small frame.
void LodBuilder::emit_fan(const Tri& t, std::uint32_t*& out) {
  const GridPolygon polygon = clip_to_grid(t, rows(), cols());
  for (int k = 0; k < polygon.count; ++k) fan_corners_.push_back(grid_.id(polygon.corner[k]));
  for (int k = 1; k + 1 < polygon.count; ++k) {
    *out++ = grid_.id(polygon.corner[0]);
    *out++ = grid_.id(polygon.corner[k]);
    *out++ = grid_.id(polygon.corner[k + 1]);
  }
}

}  // namespace pond::lod
