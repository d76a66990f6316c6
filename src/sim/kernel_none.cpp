// Builds without the AVX2 and AVX-512 backends (IA-32) link this instead of their kernels.
#include "sim/backends.h"

namespace pond::sim {
StepRowsFn step_rows_avx2(int, bool, bool) { return nullptr; }
StepRowsFn step_rows_avx512(int, bool, bool) { return nullptr; }
}  // namespace pond::sim
