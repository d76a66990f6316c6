#include "sim/backends.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <string>

#include "core/errors.h"
#include "shared/exact_math.h"

namespace pond::sim {
namespace {

// The CPU features of the SIMD backends, narrowest first: a CPU without one has none of the wider
// ones (no AVX-512F without AVX2), so masking one masks those after it too.
constexpr const char* kFeatures[] = {"sse2", "avx2", "avx512f"};

int feature_index(Backend b) { return b == Backend::sse ? 0 : b == Backend::avx2 ? 1 : 2; }

// How many of kFeatures POND_CPU_FEATURES_MASK (a comma-separated list of them) leaves visible. Read
// on every call, so a test can set it. An unknown name is an InputError rather than a mask that
// silently hides nothing.
int unmasked_features() {
  const char* mask = std::getenv("POND_CPU_FEATURES_MASK");
  int visible = static_cast<int>(std::size(kFeatures));
  for (std::string_view rest = mask ? mask : ""; !rest.empty();) {
    const std::size_t comma = rest.find(',');
    const std::string_view name = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    if (name.empty()) continue;
    const auto* f = std::find(std::begin(kFeatures), std::end(kFeatures), name);
    if (f == std::end(kFeatures))
      throw InputError("POND_CPU_FEATURES_MASK: unknown CPU feature '" + std::string(name) +
                       "' (sse2, avx2, avx512f)");
    visible = std::min(visible, static_cast<int>(f - std::begin(kFeatures)));
  }
  return visible;
}

bool masked(Backend b) { return b != Backend::scalar && feature_index(b) >= unmasked_features(); }

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
  if (!compiled_in(b) || masked(b)) return false;
  switch (b) {
    case Backend::scalar: return true;
    case Backend::sse: return __builtin_cpu_supports("sse2");
    case Backend::avx2: return __builtin_cpu_supports("avx2");
    case Backend::avx512: return __builtin_cpu_supports("avx512f");
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
