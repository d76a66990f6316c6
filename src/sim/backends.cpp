#include "sim/backends.h"

#include <string>

#include "core/cpu_features.h"
#include "core/errors.h"
#include "shared/exact_math.h"

namespace pond::sim {
namespace {

core::CpuFeature feature_of(Backend b) {
  return b == Backend::sse ? core::CpuFeature::sse2 : b == Backend::avx2 ? core::CpuFeature::avx2 : core::CpuFeature::avx512f;
}

bool masked(Backend b) { return b != Backend::scalar && core::cpu_feature_masked(feature_of(b)); }

}  // namespace

bool compiled_in(Backend b) {
  switch (b) {
    case Backend::scalar:
    case Backend::sse: return true;
    case Backend::avx2: return step_rows_avx2(shared::kRsqrtStepsExact, false, false) != nullptr;
    case Backend::avx512: return step_rows_avx512(shared::kRsqrtStepsExact, false, false) != nullptr;
  }
  return false;
}

bool cpu_supports(Backend b) {
  if (!compiled_in(b)) return false;
  return b == Backend::scalar || core::cpu_has(feature_of(b));
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

StepRowsFn step_rows_for(Backend b, int rsqrt_steps, bool reach, bool tiles) {
  if (!compiled_in(b))
    throw InputError(std::string("solver ") + backend_name(b) +
                     " is not in this build (IA-32 builds have scalar and sse)");
  if (!cpu_supports(b)) {
    const std::string feature = b == Backend::avx512 ? "AVX-512F" : b == Backend::avx2 ? "AVX2" : "SSE2";
    throw InputError(std::string("solver ") + backend_name(b) + ": " +
                     (masked(b) ? feature + " is masked out by POND_CPU_FEATURES_MASK"
                                : "this CPU lacks " + feature));
  }
  switch (b) {
    case Backend::scalar: return step_rows_scalar(rsqrt_steps, reach, tiles);
    case Backend::sse: return step_rows_sse2(rsqrt_steps, reach, tiles);
    case Backend::avx2: return step_rows_avx2(rsqrt_steps, reach, tiles);
    case Backend::avx512: return step_rows_avx512(rsqrt_steps, reach, tiles);
  }
  return nullptr;
}

}  // namespace pond::sim
