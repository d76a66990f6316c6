#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_sse2.h"

namespace pond::sim {
StepRowsFn step_rows_sse2(int rsqrt_steps, bool reach, bool tiles) {
  return step_rows_of<WideSse2>(rsqrt_steps, reach, tiles);
}
}  // namespace pond::sim
