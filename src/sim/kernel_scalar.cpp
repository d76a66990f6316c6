#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_scalar.h"

namespace pond::sim {
StepRowsFn step_rows_scalar(int rsqrt_steps, bool reach, bool tiles) {
  return step_rows_of<WideScalar>(rsqrt_steps, reach, tiles);
}
}  // namespace pond::sim
