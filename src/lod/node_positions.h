#pragma once
// A read-only strided view of the R x C node positions the LOD builder reads each frame. Node
// (row, col) has index n = row * row_pitch + col (row_pitch = cols unless the rows are padded) and
// its x, y, z at x[n * stride], y[n * stride], z[n * stride], so the same view reads the STATE.npy
// interleaved layout (stride 6), structure-of-arrays buffers (stride 1) and the GPU solver's state
// in place (stride 1, rows padded to a multiple of 4 nodes: gpu/water_layout.h) without a copy.
// The builder's own passes run on its compact copy (position_copy.h), the one reader of a pitch.
// With grid_spacing > 0 the view holds displacements from the rest grid in grid units, as the
// solvers store the state (sim/state.h) and the renderer finds it: node (row, col) is at
// ((col + x[n]) * h, y[n] * h, (row + z[n]) * h), h = grid_spacing, in float, in that order.
// LodBuilder::build converts while it copies the positions (position_copy.h), so the renderer
// writes no world positions of its own.
#include <cstddef>
#include <span>

#include "core/node_runs.h"

namespace pond::lod {

// Where only parts of the positions are on the host (a discrete GPU's state, read back in
// windows): which parts are, and a way to bring more. Null in NodePositions: every node is. The
// frame that draws implements it (render/water_source.h); not const: bringing waits.
class NodeFetch {
 public:
  virtual bool holds(const core::GridWindow& w) = 0;
  // Brings the nodes of `windows` to the host (for a GPU: one copy, one wait); the views onto the
  // positions stay valid and show them.
  virtual void bring_and_wait(std::span<const core::GridWindow> windows) = 0;

 protected:
  ~NodeFetch() = default;
};

struct NodePositions {
  const float* x = nullptr;
  const float* y = nullptr;
  const float* z = nullptr;
  std::size_t stride = 1;  // floats between two consecutive nodes' x
  int rows = 0, cols = 0;
  float grid_spacing = 0;  // > 0: displacements in grid units from the rest grid of this spacing
  std::size_t row_pitch = 0;  // nodes from a row's first node to the next row's (>= cols)
  NodeFetch* fetch = nullptr;  // where not every node is on the host (see above)

  std::size_t nodes() const { return static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols); }
};

// `data` holds rows * cols records of `stride` floats starting x, y, z (STATE.npy: stride 6).
inline NodePositions interleaved_positions(const float* data, int rows, int cols,
                                           std::size_t stride = 6) {
  return {data, data + 1, data + 2, stride, rows, cols, 0, static_cast<std::size_t>(cols), nullptr};
}

// Three separate arrays of rows * cols floats.
inline NodePositions soa_positions(const float* x, const float* y, const float* z, int rows,
                                   int cols) {
  return {x, y, z, 1, rows, cols, 0, static_cast<std::size_t>(cols), nullptr};
}

// Three arrays of displacements from the rest grid, in grid units (see the top): rows of cols
// nodes, row_pitch nodes apart (0: cols, compact).
inline NodePositions grid_displacements(const float* ux, const float* uy, const float* uz, int rows,
                                        int cols, float spacing, std::size_t row_pitch = 0) {
  return {ux, uy, uz, 1, rows, cols, spacing, row_pitch ? row_pitch : static_cast<std::size_t>(cols), nullptr};
}

}  // namespace pond::lod
