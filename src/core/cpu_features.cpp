#include "core/cpu_features.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <string>
#include <string_view>

#if defined(__aarch64__)
#include <asm/hwcap.h>
#include <sys/auxv.h>
#endif

#include "core/errors.h"

namespace pond::core {
namespace {

// In CpuFeature's order. Each family is narrowest first: masking one masks the rest of its family.
constexpr const char* kFeatures[] = {"sse2", "avx2", "avx512f", "neon"};
constexpr int kX86Features = 3;  // sse2, avx2, avx512f; then neon alone

// For each feature, whether the mask hides it.
struct Hidden {
  bool feature[std::size(kFeatures)] = {};
};

Hidden hidden_features() {
  const char* mask = std::getenv("POND_CPU_FEATURES_MASK");
  Hidden hidden;
  for (std::string_view rest = mask ? mask : ""; !rest.empty();) {
    const std::size_t comma = rest.find(',');
    const std::string_view name = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    if (name.empty()) continue;
    const auto* f = std::find(std::begin(kFeatures), std::end(kFeatures), name);
    if (f == std::end(kFeatures))
      throw InputError("POND_CPU_FEATURES_MASK: unknown CPU feature '" + std::string(name) +
                       "' (sse2, avx2, avx512f, neon)");
    const int k = static_cast<int>(f - std::begin(kFeatures));
    const int family_end = k < kX86Features ? kX86Features : static_cast<int>(std::size(kFeatures));
    for (int i = k; i < family_end; ++i) hidden.feature[i] = true;
  }
  return hidden;
}

bool cpu_reports(CpuFeature f) {
#if defined(__x86_64__) || defined(__i386__)
  switch (f) {
    case CpuFeature::sse2: return __builtin_cpu_supports("sse2");
    case CpuFeature::avx2: return __builtin_cpu_supports("avx2");
    case CpuFeature::avx512f: return __builtin_cpu_supports("avx512f");
    case CpuFeature::neon: return false;
  }
  return false;
#elif defined(__aarch64__)
  return f == CpuFeature::neon && (getauxval(AT_HWCAP) & HWCAP_ASIMD) != 0;
#else
  (void)f;
  return false;
#endif
}

}  // namespace

void validate_cpu_features_mask() { hidden_features(); }

bool cpu_feature_masked(CpuFeature f) { return hidden_features().feature[static_cast<int>(f)]; }

bool cpu_has(CpuFeature f) { return !cpu_feature_masked(f) && cpu_reports(f); }

}  // namespace pond::core
