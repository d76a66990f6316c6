#pragma once
// The one door from the CPU-only command code to the GPU solver, so `pond simulate` (and `pond
// --version`) build the same in Vulkan and in IA-32 builds (where gpu_bridge_none.cpp says the GPU
// is not in this build).
#include <string>

#include "sim/solver.h"

namespace pond::app {

struct GpuRunOptions {
  std::string device;  // empty: the first suitable device
  bool validation = false;
};

// GPU solvers for a session, on a headless Vulkan device the factory opens on first use and keeps.
sim::GpuSolverFactory headless_gpu_solvers(const GpuRunOptions& options);

// The Vulkan headers this build was compiled against, "Vulkan headers 1.3.239", or "no Vulkan".
std::string vulkan_in_build();

}  // namespace pond::app
