#pragma once
// The builder's per-frame copy of the node positions into its own structure-of-arrays buffers,
// finding the largest |coordinate| on the way (it sizes every float rounding margin).
#include "lod/node_positions.h"

namespace pond::lod {

// Copies node (row, col)'s position to x[n], y[n], z[n], n = row * cols + col (compact, whatever
// the view's row pitch; world units: a grid_displacements view is converted on the way) and returns the largest |coordinate|: +inf or NaN when some coordinate is
// not finite.
float copy_positions(const NodePositions& positions, float* x, float* y, float* z);

}  // namespace pond::lod
