#pragma once
// Explicit physical-device choice. A device qualifies when it supports Vulkan 1.3 and has a queue
// family with compute; CPU devices (lavapipe) qualify. With a name, the first qualifying device
// whose name contains it (case-insensitive) is chosen; without, the first of the most capable type
// (discrete, integrated, virtual, CPU, other).
#include <cstdint>
#include <string>

#include "gpu/vulkan.h"

namespace pond::gpu {

struct DeviceChoice {
  vk::raii::PhysicalDevice physical;
  std::uint32_t compute_family;
  std::string name;
};

// Throws RuntimeError when no device qualifies, InputError when `name` matches none (both list
// the devices seen).
// `source` prefixes `name` in messages, saying where it came from ("--device ", "POND_DEVICE=").
DeviceChoice choose_device(const vk::raii::Instance& instance, const std::string& name,
                           const std::string& source = "--device ");

}  // namespace pond::gpu
