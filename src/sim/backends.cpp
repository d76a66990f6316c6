#include "sim/backends.h"

#include "core/errors.h"
#include "shared/exact_math.h"

namespace pond::sim {

bool cpu_supports(Backend b) {
  switch (b) {
    case Backend::scalar: return true;
    case Backend::sse: return __builtin_cpu_supports("sse2");
    case Backend::avx2: return step_rows_avx2(shared::kRsqrtStepsExact) != nullptr && __builtin_cpu_supports("avx2");
    case Backend::avx512:
      return step_rows_avx512(shared::kRsqrtStepsExact) != nullptr && __builtin_cpu_supports("avx512f");
  }
  return false;
}

Backend best_backend() {
  if (cpu_supports(Backend::avx512)) return Backend::avx512;
  if (cpu_supports(Backend::avx2)) return Backend::avx2;
  if (cpu_supports(Backend::sse)) return Backend::sse;
  return Backend::scalar;
}

const char* backend_name(Backend b) {
  switch (b) {
    case Backend::scalar: return "scalar";
    case Backend::sse: return "sse";
    case Backend::avx2: return "avx2";
    case Backend::avx512: return "avx512";
  }
  return "?";
}

std::optional<Backend> parse_backend(std::string_view name) {
  for (Backend b : {Backend::scalar, Backend::sse, Backend::avx2, Backend::avx512})
    if (name == backend_name(b)) return b;
  return std::nullopt;
}

StepRowsFn step_rows_for(Backend b, int rsqrt_steps) {
  if ((b == Backend::avx2 && step_rows_avx2(rsqrt_steps) == nullptr) ||
      (b == Backend::avx512 && step_rows_avx512(rsqrt_steps) == nullptr))
    throw InputError(std::string("solver ") + backend_name(b) +
                     " is not in this build (IA-32 builds have scalar and sse)");
  if (!cpu_supports(b))
    throw InputError(std::string("solver ") + backend_name(b) + ": this CPU lacks " +
                     (b == Backend::avx512 ? "AVX-512F" : b == Backend::avx2 ? "AVX2" : "SSE2"));
  switch (b) {
    case Backend::scalar: return step_rows_scalar(rsqrt_steps);
    case Backend::sse: return step_rows_sse2(rsqrt_steps);
    case Backend::avx2: return step_rows_avx2(rsqrt_steps);
    case Backend::avx512: return step_rows_avx512(rsqrt_steps);
  }
  return nullptr;
}

}  // namespace pond::sim
