#pragma once
// The plain data one substep of the CPU kernel works on (see step_kernel.h).
#include <cstdint>

#include "shared/tile_bounds.h"
#include "sim/model.h"

namespace pond::sim {

// Input and output arrays of one substep (SoA, grid units: displacements u and velocities v) and
// the model constants.
struct StepView {
  const float *ux, *uy, *uz, *vx, *vy, *vz;
  float *oux, *ouy, *ouz, *ovx, *ovy, *ovz;
  const std::uint8_t* kinds;
  int rows, cols;
  StepConstants k;
};

// The kernel walks the grid in blocks of kBlockCols columns, each block down the rows of a thread's
// range, so its spring rows stay in the core's caches and every spring row sits at a compile-time
// offset from one base pointer. Per thread, a scratch of kSpringRows rows of kSlots floats: two
// rows of horizontal springs H (x, y, z; the current row's and the next row's) and three bands
// (below the current row, above it, and above the next row) of S, D1, D2 (x, y, z each). Slot s of
// a row holds column index j = c0 + s - 1 of the block starting at c0, so slot 0 is the column
// left of the block (or the missing column -1); the kernel may shift all slots by up to
// kSlotAlign - 1 to align its stores.
// One block spans a 1024-wide row: a substep walks the state arrays straight through rather than
// in row pieces, which beats narrower blocks (docs/perf.md), and the scratch (about 140 KB) still
// stays in L2.
inline constexpr int kBlockCols = 1024;
inline constexpr int kSlotAlign = 16;  // floats in 64 bytes
inline constexpr int kSlots = kBlockCols + 2 * kSlotAlign;  // a multiple of kSlotAlign
inline constexpr int kSpringRows = 2 * 3 + 3 * 9;

}  // namespace pond::sim

namespace pond::sim {

// Where a kernel puts the tile bounds (shared/tile_bounds.h) of its rows [r0, r1): while it walks
// a block's rows, the bounds of each column over a tile row's rows, taken at its last row (six
// rows of kColumnsPitch floats: least x, y, z, greatest x, y, z); at a tile row's end (or r1 - 1),
// the tile row from them, tile row b at rows + (b - first_row) * tiles_x (partial where the tile
// row goes on beyond [r0, r1): the solver merges those).
// A cache line more than a block, so that the six rows do not all fall in one set of the cache.
inline constexpr int kColumnsPitch = kBlockCols + kSlotAlign;
struct TileSink {
  shared::TileBounds* rows;
  float* columns;
  int first_row;  // the first tile row holding a row of [r0, r1)
};

}  // namespace pond::sim
