#pragma once
// POND_CPU_FEATURES_MASK set for one scope (core/cpu_features.h), the previous value restored after:
// for tests that run the narrower copies of the CPU code on a CPU that has the wider ones.
#include <cstdlib>
#include <optional>
#include <string>

namespace pond::test {

class CpuFeaturesMask {
 public:
  explicit CpuFeaturesMask(const char* mask) {
    if (const char* old = std::getenv(kName)) old_ = old;
    ::setenv(kName, mask, 1);
  }
  ~CpuFeaturesMask() {
    if (old_) ::setenv(kName, old_->c_str(), 1);
    else ::unsetenv(kName);
  }
  CpuFeaturesMask(const CpuFeaturesMask&) = delete;
  CpuFeaturesMask& operator=(const CpuFeaturesMask&) = delete;

 private:
  static constexpr const char* kName = "POND_CPU_FEATURES_MASK";
  std::optional<std::string> old_;
};

}  // namespace pond::test
