#pragma once
// The CPU solver backends: one kernel (step_kernel.h) instantiated for each wide-float table.
#include <optional>
#include <string>
#include <string_view>

#include "sim/step_view.h"

namespace pond::sim {

enum class Backend { scalar, sse, avx2 };

using StepRowsFn = float (*)(const StepView&, int r0, int r1, const SpringRows&);

StepRowsFn step_rows_scalar();
StepRowsFn step_rows_sse2();
StepRowsFn step_rows_avx2();  // nullptr in builds without AVX2 (IA-32)

bool cpu_supports(Backend b);        // compiled in and supported by this CPU
Backend best_backend();              // the widest supported
const char* backend_name(Backend b);  // "scalar", "sse", "avx2"
std::optional<Backend> parse_backend(std::string_view name);
StepRowsFn step_rows_for(Backend b);  // throws InputError naming the missing CPU feature

}  // namespace pond::sim
