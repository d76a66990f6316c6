#include "sim/backends.h"

#include <string>

#include "core/cpu_features.h"
#include "core/errors.h"
#include "shared/exact_math.h"

namespace pond::sim {
namespace {

core::CpuFeature feature_of(Backend b) {
  switch (b) {
    case Backend::avx2: return core::CpuFeature::avx2;
    case Backend::avx512: return core::CpuFeature::avx512f;
    case Backend::neon: return core::CpuFeature::neon;
    default: return core::CpuFeature::sse2;
  }
}

const char* feature_name(Backend b) {
  switch (b) {
    case Backend::avx2: return "AVX2";
    case Backend::avx512: return "AVX-512F";
    case Backend::neon: return "NEON";
    default: return "SSE2";
  }
}

bool masked(Backend b) { return b != Backend::scalar && core::cpu_feature_masked(feature_of(b)); }

StepRowsFn kernel(Backend b, int rsqrt_steps, bool reach, bool tiles) {
  switch (b) {
    case Backend::scalar: return step_rows_scalar(rsqrt_steps, reach, tiles);
    case Backend::sse: return step_rows_sse2(rsqrt_steps, reach, tiles);
    case Backend::avx2: return step_rows_avx2(rsqrt_steps, reach, tiles);
    case Backend::avx512: return step_rows_avx512(rsqrt_steps, reach, tiles);
    case Backend::neon: return step_rows_neon(rsqrt_steps, reach, tiles);
  }
  return nullptr;
}

}  // namespace

bool compiled_in(Backend b) { return kernel(b, shared::kRsqrtStepsExact, false, false) != nullptr; }

bool cpu_supports(Backend b) {
  if (!compiled_in(b)) return false;
  return b == Backend::scalar || core::cpu_has(feature_of(b));
}

Backend best_backend() {
  for (Backend b : {Backend::avx512, Backend::avx2, Backend::sse, Backend::neon})
    if (cpu_supports(b)) return b;
  return Backend::scalar;
}

const char* backend_name(Backend b) {
  switch (b) {
    case Backend::scalar: return "scalar";
    case Backend::sse: return "sse";
    case Backend::avx2: return "avx2";
    case Backend::avx512: return "avx512";
    case Backend::neon: return "neon";
  }
  return "?";
}

std::optional<Backend> parse_backend(std::string_view name) {
  for (Backend b : kBackends)
    if (name == backend_name(b)) return b;
  return std::nullopt;
}

StepRowsFn step_rows_for(Backend b, int rsqrt_steps, bool reach, bool tiles) {
  if (!compiled_in(b)) {
    std::string have;
    for (Backend c : kBackends)
      if (compiled_in(c)) have += std::string(have.empty() ? "" : " ") + backend_name(c);
    throw InputError(std::string("solver ") + backend_name(b) + " is not in this build (its CPU solvers: " + have + ")");
  }
  if (!cpu_supports(b)) {
    const std::string feature = feature_name(b);
    throw InputError(std::string("solver ") + backend_name(b) + ": " +
                     (masked(b) ? feature + " is masked out by POND_CPU_FEATURES_MASK"
                                : "this CPU lacks " + feature));
  }
  return kernel(b, rsqrt_steps, reach, tiles);
}

}  // namespace pond::sim
