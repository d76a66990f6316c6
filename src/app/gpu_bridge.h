#pragma once
// The one door from the CPU-only command code to the GPU solver, so `pond simulate` builds the same
// in Vulkan and in IA-32 builds (where gpu_bridge_none.cpp says the GPU is not in this build).
#include <cstdint>
#include <string>

#include "sim/model.h"
#include "sim/state.h"

namespace pond::app {

struct GpuRunOptions {
  std::string device;  // empty: the first suitable device
  bool validation = false;
};

// Runs `steps` steps of `model` from rest on the GPU and reads the state back.
sim::WaterState simulate_on_gpu(const sim::WaterModel& model, std::int64_t steps,
                                const GpuRunOptions& options);

}  // namespace pond::app
