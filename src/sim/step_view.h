#pragma once
// The plain data one substep of the CPU kernel works on (see step_kernel.h).
#include <cstdint>

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
// range, so its spring rows stay in L1 and every spring row sits at a compile-time offset from one
// base pointer. Per thread, a scratch of kSpringRows rows of kSlots floats: the horizontal springs
// H (x, y, z) and two bands (the one below the current row and the one above) of S, D1, D2
// (x, y, z each). Slot s of a row holds column index j = c0 + s - 1 of the block starting at c0,
// so slot 0 is the column left of the block (or the missing column -1).
inline constexpr int kBlockCols = 512;
inline constexpr int kSlots = kBlockCols + 8;
inline constexpr int kSpringRows = 3 + 2 * 9;

}  // namespace pond::sim
