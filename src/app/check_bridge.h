#pragma once
// The door from `pond check`'s option parsing (built everywhere) to the GPU
// (check_bridge_vulkan.cpp); IA-32 builds link check_bridge_none.cpp, which says the GPU is not in
// this build.
#include <cstdint>
#include <string>

namespace pond::app {

struct CheckOptions {
  std::string device;      // empty: the default device choice
  std::int64_t steps = 0;  // 0: each case's own length
};

// Runs the built-in cases (check_cases.h) on the GPU and on the CPU; prints the table and the
// device's float controls. 0 when every case is bit-identical, 1 when one is not.
int run_check(const CheckOptions& options);

}  // namespace pond::app
