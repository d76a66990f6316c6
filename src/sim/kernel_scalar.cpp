#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_scalar.h"

namespace pond::sim {
StepRowsFn step_rows_scalar(int rsqrt_steps, bool reach) { return step_rows_of<WideScalar>(rsqrt_steps, reach); }
}  // namespace pond::sim
