// Built with -mavx2 (see src/sim/CMakeLists.txt); only called after a run-time CPU check.
#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_avx2.h"

namespace pond::sim {
StepRowsFn step_rows_avx2(int rsqrt_steps, bool reach, bool tiles) {
  return step_rows_of<WideAvx2>(rsqrt_steps, reach, tiles);
}
}  // namespace pond::sim
