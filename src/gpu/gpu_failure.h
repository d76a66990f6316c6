#pragma once
// Vulkan's failures that end a device's work, as pond's GpuFailure (core/errors.h): a lost device
// (VK_ERROR_DEVICE_LOST) and memory it cannot allocate (VK_ERROR_OUT_OF_DEVICE_MEMORY,
// VK_ERROR_OUT_OF_HOST_MEMORY), each in one line naming the device and what pond was doing. Other
// Vulkan errors become RuntimeErrors the same way. The GPU solver's entry points and the front
// ends' Vulkan code pass their work through guard_gpu(), so a session can tell a GPU failure
// from any other and go on on the CPU.
#include <string>
#include <utility>

#include "core/errors.h"
#include "gpu/context.h"

namespace pond::gpu {

// The current exception (a vk::SystemError) as pond's error; any other exception as it is.
[[noreturn]] void rethrow_as_gpu_failure(const std::string& device, const char* doing);

template <class F>
decltype(auto) guard_gpu(const std::string& device, const char* doing, F&& work) {
  try {
    return std::forward<F>(work)();
  } catch (const vk::SystemError&) {
    rethrow_as_gpu_failure(device, doing);
  }
}

template <class F>
decltype(auto) guard_gpu(const Context& ctx, const char* doing, F&& work) {
  return guard_gpu(ctx.device_name(), doing, std::forward<F>(work));
}

}  // namespace pond::gpu
