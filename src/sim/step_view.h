#pragma once
// The plain data one substep of the CPU kernel works on (see step_kernel.h).
#include <cstdint>

#include "sim/model.h"

namespace pond::sim {

// Input and output arrays of one substep (SoA, grid units) and the model constants.
struct StepView {
  const float *x, *y, *z, *vx, *vy, *vz;
  float *ox, *oy, *oz, *ovx, *ovy, *ovz;
  const std::uint8_t* kinds;
  int rows, cols;
  StepConstants k;
};

// Per-thread spring rows: slot s holds index j = s - 1, so index -1 (a missing left neighbour)
// is slot 0 and index cols-1 is slot cols.
struct SpringRows {
  float* h[3];
  float* s[2][3];  // [band][component]; which band is "below" alternates row by row
  float* d1[2][3];
  float* d2[2][3];
};

}  // namespace pond::sim
