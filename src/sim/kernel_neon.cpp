// The aarch64 build's wide backend: NEON is in every aarch64 CPU, so no flags of its own.
#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_neon.h"

namespace pond::sim {
StepRowsFn step_rows_neon(int rsqrt_steps, bool reach, bool tiles) {
  return step_rows_of<WideNeon>(rsqrt_steps, reach, tiles);
}
}  // namespace pond::sim
