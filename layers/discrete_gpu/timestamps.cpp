// POND_DISCRETE_GPU_NO_TIMESTAMPS=1: the presented device has no timestamps, as some do
// (timestampComputeAndGraphics false, timestampValidBits 0 on every queue family), so that pond's
// path without per-pass GPU times runs here. Read on every query.
#include <cstdlib>
#include <cstring>

#include "layer.h"

namespace pond::layer {

bool hides_timestamps() {
  const char* value = std::getenv("POND_DISCRETE_GPU_NO_TIMESTAMPS");
  return value && std::strcmp(value, "1") == 0;
}

VKAPI_ATTR void VKAPI_CALL get_physical_device_queue_family_properties(VkPhysicalDevice physical, std::uint32_t* count,
                                                                       VkQueueFamilyProperties* families) {
  instance_dispatch(dispatch_key(physical)).get_queue_families(physical, count, families);
  if (families && hides_timestamps())
    for (std::uint32_t k = 0; k < *count; ++k) families[k].timestampValidBits = 0;
}

VKAPI_ATTR void VKAPI_CALL get_physical_device_queue_family_properties2(VkPhysicalDevice physical, std::uint32_t* count,
                                                                        VkQueueFamilyProperties2* families) {
  instance_dispatch(dispatch_key(physical)).get_queue_families2(physical, count, families);
  if (families && hides_timestamps())
    for (std::uint32_t k = 0; k < *count; ++k) families[k].queueFamilyProperties.timestampValidBits = 0;
}

}  // namespace pond::layer
