#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_scalar.h"

namespace pond::sim {
StepRowsFn step_rows_scalar(int rsqrt_steps) {
  return rsqrt_steps == shared::kRsqrtStepsFast ? &step_rows<WideScalar, shared::kRsqrtStepsFast>
                                                : &step_rows<WideScalar, shared::kRsqrtStepsExact>;
}
}  // namespace pond::sim
