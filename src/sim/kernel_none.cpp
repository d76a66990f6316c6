// Builds without an AVX2 backend (IA-32) link this instead of kernel_avx2.cpp.
#include "sim/backends.h"

namespace pond::sim {
StepRowsFn step_rows_avx2(int) { return nullptr; }
}  // namespace pond::sim
