#pragma once
// The CPU solver backends: one kernel (step_kernel.h) instantiated for each wide-float table.
#include <optional>
#include <string>
#include <string_view>

#include "sim/step_view.h"

namespace pond::sim {

enum class Backend { scalar, sse, avx2, avx512, neon };
inline constexpr Backend kBackends[] = {Backend::scalar, Backend::sse, Backend::avx2, Backend::avx512, Backend::neon};

// A substep of rows [r0, r1) with a scratch of kSpringRows * kSlots floats. Returns the blow-up
// check; a kernel that tracks the reach also stores the rows' largest |u'x|, |u'z| in *reach.
// A kernel that emits the tile bounds of the new displacements does so to *tiles (else nullptr).
using StepRowsFn = float (*)(const StepView&, int r0, int r1, float* scratch, float* reach, TileSink* tiles);

// The kernel of one backend for a number of Newton steps (shared::kRsqrtStepsExact or ...Fast),
// tracking the reach (scenes with bodies) or not, emitting the tile bounds (to its TileSink) or not.
StepRowsFn step_rows_scalar(int rsqrt_steps, bool reach, bool tiles);
StepRowsFn step_rows_sse2(int rsqrt_steps, bool reach, bool tiles);
// Each wide one is nullptr where the build's target has not that backend (kernel_none.cpp): x86-64
// builds have sse, avx2, avx512; IA-32 builds sse; aarch64 builds neon.
StepRowsFn step_rows_avx2(int rsqrt_steps, bool reach, bool tiles);
StepRowsFn step_rows_avx512(int rsqrt_steps, bool reach, bool tiles);
StepRowsFn step_rows_neon(int rsqrt_steps, bool reach, bool tiles);

// Tests hide CPU features with POND_CPU_FEATURES_MASK (core/cpu_features.h).
bool compiled_in(Backend b);         // in this build (scalar always; the wide ones: above)
bool cpu_supports(Backend b);        // compiled in, supported by this CPU and not masked (line above)
Backend best_backend();              // the widest supported
const char* backend_name(Backend b);  // "scalar", "sse", "avx2", "avx512", "neon"
std::optional<Backend> parse_backend(std::string_view name);
StepRowsFn step_rows_for(Backend b, int rsqrt_steps, bool reach, bool tiles);  // throws InputError naming the missing CPU feature

}  // namespace pond::sim
