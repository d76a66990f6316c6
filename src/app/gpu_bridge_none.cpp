#include "app/gpu_bridge.h"
#include "core/errors.h"

namespace pond::app {

sim::GpuSolverFactory headless_gpu_solvers(const GpuRunOptions&) {
  return [](const sim::WaterModel&) -> std::unique_ptr<sim::Solver> {
    throw InputError("--solver gpu: this build has no GPU solver (IA-32 builds are CPU-only)");
  };
}

std::string vulkan_in_build() { return "no Vulkan"; }

}  // namespace pond::app
