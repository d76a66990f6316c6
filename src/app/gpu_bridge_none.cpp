#include "app/gpu_bridge.h"
#include "core/errors.h"

namespace pond::app {

sim::WaterState simulate_on_gpu(const sim::WaterModel&, std::int64_t, const GpuRunOptions&) {
  throw InputError("--solver gpu: this build has no GPU solver (IA-32 builds are CPU-only)");
}

}  // namespace pond::app
