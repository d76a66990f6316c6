// The layer's counters (layer.h, Counters): each intercepted submission and host wait counts once,
// then goes to the next layer, unless a fault made the device lost (faults.cpp): then every call
// here that may return VK_ERROR_DEVICE_LOST does, as on a lost device. The registry's lock is held
// only to find the device's state, never across a wait.
#include <cinttypes>
#include <cstdio>
#include <cstdlib>

#include "layer.h"

namespace pond::layer {

DeviceState* find_device_state(void* key) {
  std::lock_guard lock(registry().mutex);
  const auto it = registry().devices.find(key);
  return it == registry().devices.end() ? nullptr : it->second.get();
}

std::string counters_json(const Counters& c) {
  char text[256];
  std::snprintf(text, sizeof text,
                "{\"submits\": %" PRIu64 ", \"host_waits\": %" PRIu64 ", \"bytes_flushed\": %" PRIu64
                ", \"bytes_invalidated\": %" PRIu64 ", \"allocations\": %" PRIu64 "}\n",
                c.submits.load(), c.host_waits.load(), c.bytes_flushed.load(), c.bytes_invalidated.load(),
                c.allocations.load());
  return text;
}

void write_counters(const Counters& counters) {
  const char* path = std::getenv("POND_DISCRETE_GPU_STATS");
  if (!path || !*path) return;
  std::FILE* f = std::fopen(path, "w");
  if (!f) {
    report("POND_DISCRETE_GPU_STATS: cannot write %s", path);
    return;
  }
  const std::string json = counters_json(counters);
  std::fputs(json.c_str(), f);
  if (std::fclose(f) != 0) report("POND_DISCRETE_GPU_STATS: cannot write %s", path);
}

VKAPI_ATTR VkResult VKAPI_CALL queue_submit(VkQueue queue, std::uint32_t count, const VkSubmitInfo* submits,
                                            VkFence fence) {
  DeviceState* d = find_device_state(dispatch_key(queue));
  if (!d) return VK_ERROR_DEVICE_LOST;
  ++d->counters.submits;
  if (submit_fault(*d)) return VK_ERROR_DEVICE_LOST;
  return d->next.queue_submit(queue, count, submits, fence);
}

VKAPI_ATTR VkResult VKAPI_CALL queue_submit2(VkQueue queue, std::uint32_t count, const VkSubmitInfo2* submits,
                                             VkFence fence) {
  DeviceState* d = find_device_state(dispatch_key(queue));
  if (!d) return VK_ERROR_DEVICE_LOST;
  ++d->counters.submits;
  if (submit_fault(*d)) return VK_ERROR_DEVICE_LOST;
  return d->next.queue_submit2(queue, count, submits, fence);
}

VKAPI_ATTR VkResult VKAPI_CALL wait_for_fences(VkDevice device, std::uint32_t count, const VkFence* fences,
                                               VkBool32 wait_all, std::uint64_t timeout) {
  DeviceState* d = find_device_state(dispatch_key(device));
  if (!d) return VK_ERROR_DEVICE_LOST;
  ++d->counters.host_waits;
  if (d->lost) return VK_ERROR_DEVICE_LOST;
  return d->next.wait_for_fences(device, count, fences, wait_all, timeout);
}

VKAPI_ATTR VkResult VKAPI_CALL queue_wait_idle(VkQueue queue) {
  DeviceState* d = find_device_state(dispatch_key(queue));
  if (!d) return VK_ERROR_DEVICE_LOST;
  ++d->counters.host_waits;
  if (d->lost) return VK_ERROR_DEVICE_LOST;
  return d->next.queue_wait_idle(queue);
}

VKAPI_ATTR VkResult VKAPI_CALL device_wait_idle(VkDevice device) {
  DeviceState* d = find_device_state(dispatch_key(device));
  if (!d) return VK_ERROR_DEVICE_LOST;
  ++d->counters.host_waits;
  if (d->lost) return VK_ERROR_DEVICE_LOST;
  return d->next.device_wait_idle(device);
}

VKAPI_ATTR VkResult VKAPI_CALL wait_semaphores(VkDevice device, const VkSemaphoreWaitInfo* info,
                                               std::uint64_t timeout) {
  DeviceState* d = find_device_state(dispatch_key(device));
  if (!d) return VK_ERROR_DEVICE_LOST;
  ++d->counters.host_waits;
  if (d->lost) return VK_ERROR_DEVICE_LOST;
  return d->next.wait_semaphores(device, info, timeout);
}

VKAPI_ATTR VkResult VKAPI_CALL get_fence_status(VkDevice device, VkFence fence) {
  DeviceState* d = find_device_state(dispatch_key(device));
  if (!d || d->lost) return VK_ERROR_DEVICE_LOST;
  return d->next.get_fence_status(device, fence);
}

VKAPI_ATTR VkResult VKAPI_CALL acquire_next_image(VkDevice device, VkSwapchainKHR swapchain, std::uint64_t timeout,
                                                  VkSemaphore semaphore, VkFence fence, std::uint32_t* index) {
  DeviceState* d = find_device_state(dispatch_key(device));
  if (!d || d->lost) return VK_ERROR_DEVICE_LOST;
  return d->next.acquire_next_image(device, swapchain, timeout, semaphore, fence, index);
}

VKAPI_ATTR VkResult VKAPI_CALL queue_present(VkQueue queue, const VkPresentInfoKHR* info) {
  DeviceState* d = find_device_state(dispatch_key(queue));
  if (!d || d->lost) return VK_ERROR_DEVICE_LOST;
  return d->next.queue_present(queue, info);
}

VKAPI_ATTR VkResult VKAPI_CALL get_query_pool_results(VkDevice device, VkQueryPool pool, std::uint32_t first,
                                                      std::uint32_t count, std::size_t size, void* data,
                                                      VkDeviceSize stride, VkQueryResultFlags flags) {
  DeviceState* d = find_device_state(dispatch_key(device));
  if (!d || d->lost) return VK_ERROR_DEVICE_LOST;
  return d->next.get_query_pool_results(device, pool, first, count, size, data, stride, flags);
}

}  // namespace pond::layer
