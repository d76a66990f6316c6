#include "sim/backends.h"
#include "sim/step_kernel.h"
#include "sim/wide_sse2.h"

namespace pond::sim {
StepRowsFn step_rows_sse2() { return &step_rows<WideSse2>; }
}  // namespace pond::sim
