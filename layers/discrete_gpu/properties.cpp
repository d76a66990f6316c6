// What the presented device reports: its type, its limits, its features, and whether it preserves
// float32 denormals. Every query asks the next layer and rewrites the answer; nothing is cached.
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "layer.h"

namespace pond::layer {
namespace {

// Limits of the presented device where a common desktop GPU is stricter than lavapipe (docs/layer.md
// gives the sources). Each only ever tightens lavapipe's value.
constexpr std::uint32_t kMaxWorkGroupSizeZ = 64;            // NVIDIA and Intel Arc (AMD: 1024)
constexpr std::uint32_t kMaxMemoryAllocationCount = 4096;   // the Vulkan minimum
constexpr std::uint32_t kMaxSamplerAllocationCount = 4000;  // the Vulkan minimum, NVIDIA's value
// NVIDIA's and Intel's subgroup size (lavapipe: 8). Only the answer changes, so it must not be used
// by shaders with subgroup operations (pond has none): it steers pond's workgroup sizes, so the
// paths sized for a desktop GPU run here.
constexpr std::uint32_t kSubgroupSize = 32;

// POND_DISCRETE_GPU_DENORM_PRESERVE=0|1 (default 1, as most desktop drivers): whether the device
// advertises shaderDenormPreserveFloat32, so pond's paths for both answers run here. Read on every
// query, so a test may change it between instances.
bool denorm_preserve() {
  const char* value = std::getenv("POND_DISCRETE_GPU_DENORM_PRESERVE");
  if (!value || !*value || std::strcmp(value, "1") == 0) return true;
  if (std::strcmp(value, "0") == 0) return false;
  static std::atomic<bool> warned{false};
  if (!warned.exchange(true)) report("POND_DISCRETE_GPU_DENORM_PRESERVE=%s is neither 0 nor 1; using 1", value);
  return true;
}

// POND_DISCRETE_GPU_MAX_TEXEL_BUFFER_ELEMENTS=N (optional): a lower maxTexelBufferElements, down to
// the Vulkan minimum 65536, so a test can see pond refuse what such a device cannot view.
std::uint32_t max_texel_buffer_elements(std::uint32_t lavapipe) {
  const char* value = std::getenv("POND_DISCRETE_GPU_MAX_TEXEL_BUFFER_ELEMENTS");
  if (!value || !*value) return lavapipe;
  // Digits only: strtoul alone takes a sign (negating "-18446744073709486080" to 65536) and
  // saturates on overflow.
  char* end = nullptr;
  errno = 0;
  const unsigned long n = value[0] >= '0' && value[0] <= '9' ? std::strtoul(value, &end, 10) : 0;
  if (!end || *end || errno == ERANGE || n < 65536) {
    static std::atomic<bool> warned{false};
    if (!warned.exchange(true))
      report("POND_DISCRETE_GPU_MAX_TEXEL_BUFFER_ELEMENTS=%s is not a number >= 65536; ignored", value);
    return lavapipe;
  }
  return static_cast<std::uint32_t>(std::min<unsigned long>(n, lavapipe));
}

template <typename T>
T* find_in_chain(void* chain, VkStructureType type) {
  for (auto* s = static_cast<VkBaseOutStructure*>(chain); s; s = s->pNext)
    if (s->sType == type) return reinterpret_cast<T*>(s);
  return nullptr;
}

void present(VkPhysicalDeviceProperties& p) {
  p.deviceType = VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  VkPhysicalDeviceLimits& l = p.limits;
  l.nonCoherentAtomSize = std::max(l.nonCoherentAtomSize, kAtomSize);
  l.maxComputeWorkGroupSize[2] = std::min(l.maxComputeWorkGroupSize[2], kMaxWorkGroupSizeZ);
  l.maxMemoryAllocationCount = std::min(l.maxMemoryAllocationCount, kMaxMemoryAllocationCount);
  l.maxSamplerAllocationCount = std::min(l.maxSamplerAllocationCount, kMaxSamplerAllocationCount);
  l.maxTexelBufferElements = max_texel_buffer_elements(l.maxTexelBufferElements);
  if (hides_timestamps()) l.timestampComputeAndGraphics = VK_FALSE;
}

void present(VkPhysicalDeviceFeatures& f) { f.shaderInt64 = VK_FALSE; }

}  // namespace

VKAPI_ATTR void VKAPI_CALL get_physical_device_properties(VkPhysicalDevice physical,
                                                          VkPhysicalDeviceProperties* properties) {
  instance_dispatch(dispatch_key(physical)).get_properties(physical, properties);
  present(*properties);
}

VKAPI_ATTR void VKAPI_CALL get_physical_device_properties2(VkPhysicalDevice physical,
                                                           VkPhysicalDeviceProperties2* properties) {
  instance_dispatch(dispatch_key(physical)).get_properties2(physical, properties);
  present(properties->properties);
  // Only the denormal answer changes; flush-to-zero and the independence stay lavapipe's (it
  // cannot flush on request, and it treats every width independently).
  const VkBool32 preserve = denorm_preserve() ? VK_TRUE : VK_FALSE;
  if (auto* v12 = find_in_chain<VkPhysicalDeviceVulkan12Properties>(
          properties->pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_PROPERTIES))
    v12->shaderDenormPreserveFloat32 = preserve;
  if (auto* controls = find_in_chain<VkPhysicalDeviceFloatControlsProperties>(
          properties->pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FLOAT_CONTROLS_PROPERTIES))
    controls->shaderDenormPreserveFloat32 = preserve;
  if (auto* v11 = find_in_chain<VkPhysicalDeviceVulkan11Properties>(
          properties->pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES))
    v11->subgroupSize = kSubgroupSize;
  if (auto* subgroup = find_in_chain<VkPhysicalDeviceSubgroupProperties>(
          properties->pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES))
    subgroup->subgroupSize = kSubgroupSize;
}

VKAPI_ATTR void VKAPI_CALL get_physical_device_features(VkPhysicalDevice physical,
                                                        VkPhysicalDeviceFeatures* features) {
  instance_dispatch(dispatch_key(physical)).get_features(physical, features);
  present(*features);
}

// The 64-bit atomics go with shaderInt64: their SPIR-V needs the Int64 capability.
VKAPI_ATTR void VKAPI_CALL get_physical_device_features2(VkPhysicalDevice physical,
                                                         VkPhysicalDeviceFeatures2* features) {
  instance_dispatch(dispatch_key(physical)).get_features2(physical, features);
  present(features->features);
  if (auto* v12 = find_in_chain<VkPhysicalDeviceVulkan12Features>(
          features->pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES)) {
    v12->shaderBufferInt64Atomics = VK_FALSE;
    v12->shaderSharedInt64Atomics = VK_FALSE;
  }
  if (auto* atomics = find_in_chain<VkPhysicalDeviceShaderAtomicInt64Features>(
          features->pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_INT64_FEATURES)) {
    atomics->shaderBufferInt64Atomics = VK_FALSE;
    atomics->shaderSharedInt64Atomics = VK_FALSE;
  }
}

bool requests_hidden_feature(const VkDeviceCreateInfo& info) {
  const char* feature = nullptr;
  if (info.pEnabledFeatures && info.pEnabledFeatures->shaderInt64) feature = "shaderInt64";
  for (auto* s = static_cast<const VkBaseInStructure*>(info.pNext); s && !feature; s = s->pNext) {
    if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2) {
      if (reinterpret_cast<const VkPhysicalDeviceFeatures2*>(s)->features.shaderInt64) feature = "shaderInt64";
    } else if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES) {
      const auto* v12 = reinterpret_cast<const VkPhysicalDeviceVulkan12Features*>(s);
      if (v12->shaderBufferInt64Atomics || v12->shaderSharedInt64Atomics) feature = "64-bit integer atomics";
    } else if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_INT64_FEATURES) {
      const auto* a = reinterpret_cast<const VkPhysicalDeviceShaderAtomicInt64Features*>(s);
      if (a->shaderBufferInt64Atomics || a->shaderSharedInt64Atomics) feature = "64-bit integer atomics";
    }
  }
  if (feature)
    report("vkCreateDevice: %s is not supported by the presented device; VK_ERROR_FEATURE_NOT_PRESENT", feature);
  return feature != nullptr;
}

}  // namespace pond::layer
