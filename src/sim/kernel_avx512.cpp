// Built with -mavx512f (see src/sim/CMakeLists.txt); only called after a run-time CPU check.
#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_avx512.h"

namespace pond::sim {
StepRowsFn step_rows_avx512(int rsqrt_steps, bool reach, bool tiles) {
  return step_rows_of<WideAvx512>(rsqrt_steps, reach, tiles);
}
}  // namespace pond::sim
