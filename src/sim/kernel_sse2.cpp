#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_sse2.h"

namespace pond::sim {
StepRowsFn step_rows_sse2(int rsqrt_steps) {
  return rsqrt_steps == shared::kRsqrtStepsFast ? &step_rows<WideSse2, shared::kRsqrtStepsFast>
                                                : &step_rows<WideSse2, shared::kRsqrtStepsExact>;
}
}  // namespace pond::sim
