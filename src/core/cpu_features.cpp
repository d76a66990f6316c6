#include "core/cpu_features.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <string>
#include <string_view>

#include "core/errors.h"

namespace pond::core {
namespace {

// Narrowest first: a CPU without one has none of the wider ones (no AVX-512F without AVX2), so
// masking one masks those after it too.
constexpr const char* kFeatures[] = {"sse2", "avx2", "avx512f"};

// How many of kFeatures the mask leaves visible.
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

}  // namespace

void validate_cpu_features_mask() { unmasked_features(); }

bool cpu_feature_masked(CpuFeature f) { return static_cast<int>(f) >= unmasked_features(); }

bool cpu_has(CpuFeature f) {
  if (cpu_feature_masked(f)) return false;
  switch (f) {
    case CpuFeature::sse2: return __builtin_cpu_supports("sse2");
    case CpuFeature::avx2: return __builtin_cpu_supports("avx2");
    case CpuFeature::avx512f: return __builtin_cpu_supports("avx512f");
  }
  return false;
}

}  // namespace pond::core
