#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_scalar.h"

namespace pond::sim {
StepRowsFn step_rows_scalar() { return &step_rows<WideScalar>; }
}  // namespace pond::sim
