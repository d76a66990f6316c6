#include "gpu/device_choice.h"

#include <algorithm>
#include <cctype>
#include <optional>

#include "core/errors.h"

namespace pond::gpu {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

int type_rank(vk::PhysicalDeviceType t) {
  switch (t) {
    case vk::PhysicalDeviceType::eDiscreteGpu: return 0;
    case vk::PhysicalDeviceType::eIntegratedGpu: return 1;
    case vk::PhysicalDeviceType::eVirtualGpu: return 2;
    case vk::PhysicalDeviceType::eCpu: return 3;
    default: return 4;
  }
}

// A family with compute, preferably one that also does graphics: the renderer records its draws on
// the same queue right behind the solver's dispatches.
std::optional<std::uint32_t> compute_family(const vk::raii::PhysicalDevice& d) {
  const auto families = d.getQueueFamilyProperties();
  const auto both = vk::QueueFlagBits::eCompute | vk::QueueFlagBits::eGraphics;
  for (std::uint32_t f = 0; f < families.size(); ++f)
    if ((families[f].queueFlags & both) == both) return f;
  for (std::uint32_t f = 0; f < families.size(); ++f)
    if (families[f].queueFlags & vk::QueueFlagBits::eCompute) return f;
  return std::nullopt;
}

}  // namespace

DeviceChoice choose_device(const vk::raii::Instance& instance, const std::string& name, const std::string& source) {
  vk::raii::PhysicalDevices devices(instance);
  std::string seen;
  std::optional<std::size_t> best;
  int best_rank = 1 << 30;
  for (std::size_t k = 0; k < devices.size(); ++k) {
    const vk::PhysicalDeviceProperties p = devices[k].getProperties();
    const std::string dev_name = p.deviceName.data();
    const bool ok = p.apiVersion >= VK_API_VERSION_1_3 && compute_family(devices[k]).has_value();
    seen += (seen.empty() ? "" : ", ") + dev_name + (ok ? "" : " (no Vulkan 1.3 compute)");
    if (!ok) continue;
    if (!name.empty() && lower(dev_name).find(lower(name)) == std::string::npos) continue;
    const int rank = name.empty() ? type_rank(p.deviceType) : 0;
    if (rank < best_rank) best = k, best_rank = rank;
  }
  if (seen.empty()) throw RuntimeError("no Vulkan device found (is a Vulkan driver installed?)");
  if (!best) {
    if (!name.empty()) throw InputError(source + name + ": no Vulkan 1.3 compute device matches; devices: " + seen);
    throw RuntimeError("no Vulkan 1.3 device with compute; devices: " + seen);
  }
  vk::raii::PhysicalDevice chosen = std::move(devices[*best]);
  const std::uint32_t family = *compute_family(chosen);
  std::string chosen_name = chosen.getProperties().deviceName.data();
  return DeviceChoice{std::move(chosen), family, std::move(chosen_name)};
}

}  // namespace pond::gpu
