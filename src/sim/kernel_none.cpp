// The backends the build's target has not (cmake/CompilerFlags.cmake: POND_WIDE_BACKENDS) have no
// kernel: src/sim/CMakeLists.txt defines POND_NO_KERNEL_<ISA> for each.
#include "sim/backends.h"

namespace pond::sim {
#ifdef POND_NO_KERNEL_SSE2
StepRowsFn step_rows_sse2(int, bool, bool) { return nullptr; }
#endif
#ifdef POND_NO_KERNEL_AVX2
StepRowsFn step_rows_avx2(int, bool, bool) { return nullptr; }
#endif
#ifdef POND_NO_KERNEL_AVX512
StepRowsFn step_rows_avx512(int, bool, bool) { return nullptr; }
#endif
#ifdef POND_NO_KERNEL_NEON
StepRowsFn step_rows_neon(int, bool, bool) { return nullptr; }
#endif
}  // namespace pond::sim
