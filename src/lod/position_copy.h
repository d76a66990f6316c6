#pragma once
// The builder's per-frame copy of the node positions into its own structure-of-arrays buffers,
// finding the largest |coordinate| on the way (it sizes every float rounding margin).
#include <array>
#include <cstdint>
#include <span>

#include "lod/node_positions.h"

namespace pond::lod {

// Copies node (row, col)'s position to x[n], y[n], z[n], n = row * cols + col (compact, whatever
// the view's row pitch; world units: a grid_displacements view is converted on the way) and returns the largest |coordinate|: +inf or NaN when some coordinate is
// not finite.
float copy_positions(const NodePositions& positions, float* x, float* y, float* z);

// The same for the window of `rows` x `cols` nodes whose first node is (row0, col0) in the grid,
// copied compactly (window row i to x[i * cols ...]); world positions bit-identical to the whole
// copy's.
float copy_window(const NodePositions& positions, int row0, int col0, int rows, int cols, float* x, float* y,
                  float* z);

// copy_window(), throwing InputError naming the first node (its grid index, row and column) with a
// non-finite coordinate.
float copy_finite_window(const NodePositions& positions, int row0, int col0, int rows, int cols, float* x, float* y,
                         float* z);

// copy_finite_window() without the largest: only the check, which costs less (the builder's blocks).
// With `wide`, windows at least eight nodes wide of arrays, or of records of world positions
// starting x, y, z, go by the AVX2 copy where the build has it and the CPU runs it (camera_budget.h:
// wide_budgets_available()): the same bits.
void copy_finite_block(const NodePositions& positions, int row0, int col0, int rows, int cols, float* x, float* y,
                       float* z, bool wide = false);
// That AVX2 copy (position_copy_avx2.cpp; not in IA-32 builds): true when some coordinate may not
// be finite.
bool copy_block_avx2(const NodePositions& positions, int row0, int col0, int rows, int cols, float* x, float* y,
                     float* z);

// Node (row, col)'s world position, as the copies compute it.
std::array<float, 3> world_position(const NodePositions& positions, int row, int col);

// World positions of the nodes `ids` only (node index = row * cols + col), to x[id], y[id], z[id];
// bit-identical to the whole copy's.
void copy_nodes(const NodePositions& positions, std::span<const std::uint32_t> ids, float* x, float* y, float* z);

}  // namespace pond::lod
