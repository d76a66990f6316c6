#pragma once
// VK_LAYER_POND_discrete_gpu: a test layer that presents lavapipe (a CPU device whose one memory
// type is device-local, host-visible and coherent) as a discrete GPU, so that the paths pond takes
// on real GPUs — staging, flush/invalidate, no 64-bit integers — run and are checked here.
//
//   layer.cpp       loader interface, dispatch, instance and device creation
//   properties.cpp  device type, limits, features, the denormal setting
//   memory.cpp      the presented memory types and the non-coherent memory model
//   counters.cpp    per device: submissions, host waits, bytes flushed and invalidated
//   faults.cpp      faults on demand: a lost device, memory that cannot be allocated
//
// Only what is needed is kept: the loader's dispatch tables (immutable after creation) and, per
// device, its memory-type map and the allocations (size, type, the current mapping). Properties
// are rewritten on every query, so a setting changed between queries takes effect at once.
#define VK_NO_PROTOTYPES  // never call the loader from inside the layer: only the next layer
#include <vulkan/vk_layer.h>
#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace pond::layer {

inline constexpr const char* kLayerName = "VK_LAYER_POND_discrete_gpu";

// The non-coherent atom the layer presents and enforces: the largest the Vulkan spec allows, so
// code that rounds to lavapipe's 64 (or to nothing) is caught.
inline constexpr VkDeviceSize kAtomSize = 256;

// One line on stderr, prefixed with the layer's name: the layer's only way to say why it refused.
void report(const char* format, ...) __attribute__((format(printf, 1, 2)));

// The loader's dispatch key: the first word of every dispatchable handle points at the loader's
// dispatch table. An instance and its physical devices share one key; so do a device, its queues
// and command buffers.
template <typename Handle>
void* dispatch_key(Handle handle) {
  return *reinterpret_cast<void**>(handle);
}

// The next layer's instance-level functions this layer calls.
struct InstanceDispatch {
  VkInstance instance = VK_NULL_HANDLE;
  PFN_vkGetInstanceProcAddr get_proc_addr = nullptr;
  PFN_vkDestroyInstance destroy_instance = nullptr;
  PFN_vkGetPhysicalDeviceProperties get_properties = nullptr;
  PFN_vkGetPhysicalDeviceProperties2 get_properties2 = nullptr;
  PFN_vkGetPhysicalDeviceFeatures get_features = nullptr;
  PFN_vkGetPhysicalDeviceFeatures2 get_features2 = nullptr;
  PFN_vkGetPhysicalDeviceMemoryProperties get_memory_properties = nullptr;
  PFN_vkGetPhysicalDeviceMemoryProperties2 get_memory_properties2 = nullptr;
  PFN_vkGetPhysicalDeviceQueueFamilyProperties get_queue_families = nullptr;
  PFN_vkGetPhysicalDeviceQueueFamilyProperties2 get_queue_families2 = nullptr;
};

// The next layer's device-level functions this layer calls.
struct DeviceDispatch {
  PFN_vkGetDeviceProcAddr get_proc_addr = nullptr;
  PFN_vkDestroyDevice destroy_device = nullptr;
  PFN_vkAllocateMemory allocate_memory = nullptr;
  PFN_vkFreeMemory free_memory = nullptr;
  PFN_vkMapMemory map_memory = nullptr;
  PFN_vkUnmapMemory unmap_memory = nullptr;
  PFN_vkFlushMappedMemoryRanges flush_ranges = nullptr;
  PFN_vkInvalidateMappedMemoryRanges invalidate_ranges = nullptr;
  PFN_vkGetBufferMemoryRequirements buffer_requirements = nullptr;
  PFN_vkGetImageMemoryRequirements image_requirements = nullptr;
  PFN_vkGetBufferMemoryRequirements2 buffer_requirements2 = nullptr;
  PFN_vkGetImageMemoryRequirements2 image_requirements2 = nullptr;
  PFN_vkGetDeviceBufferMemoryRequirements device_buffer_requirements = nullptr;
  PFN_vkGetDeviceImageMemoryRequirements device_image_requirements = nullptr;
  PFN_vkQueueSubmit queue_submit = nullptr;
  PFN_vkQueueSubmit2 queue_submit2 = nullptr;
  PFN_vkWaitForFences wait_for_fences = nullptr;
  PFN_vkQueueWaitIdle queue_wait_idle = nullptr;
  PFN_vkDeviceWaitIdle device_wait_idle = nullptr;
  PFN_vkWaitSemaphores wait_semaphores = nullptr;
  PFN_vkGetFenceStatus get_fence_status = nullptr;
  PFN_vkAcquireNextImageKHR acquire_next_image = nullptr;
  PFN_vkQueuePresentKHR queue_present = nullptr;
  PFN_vkGetQueryPoolResults get_query_pool_results = nullptr;
};

// What an application did with the device, counted for tests of how it drives a GPU: every
// vkQueueSubmit / vkQueueSubmit2 call; every host wait (vkWaitForFences, vkQueueWaitIdle,
// vkDeviceWaitIdle, vkWaitSemaphores; polling a fence, acquiring and presenting are not waits);
// the bytes of every flushed and invalidated range (VK_WHOLE_SIZE: to the end of the mapping).
// Written as one JSON object to $POND_DISCRETE_GPU_STATS when the device is destroyed.
struct Counters {
  std::atomic<std::uint64_t> submits{0}, host_waits{0}, bytes_flushed{0}, bytes_invalidated{0}, allocations{0};
};
// The counters as one JSON object: {"submits": S, "host_waits": W, "bytes_flushed": F, "bytes_invalidated": I,
// "allocations": A} (A: vkAllocateMemory calls, the points POND_DISCRETE_GPU_FAULT can fail).
std::string counters_json(const Counters& counters);
// Writes counters_json to the file $POND_DISCRETE_GPU_STATS names (nothing when it is unset).
void write_counters(const Counters& counters);

// The memory types and heaps the application sees, each type backed by one real type.
struct MemoryModel {
  VkPhysicalDeviceMemoryProperties real{};
  VkPhysicalDeviceMemoryProperties presented{};
  std::uint32_t real_type[VK_MAX_MEMORY_TYPES]{};
};
MemoryModel make_memory_model(const VkPhysicalDeviceMemoryProperties& real);
// Which presented types may back a resource the driver allows in the real types `real_bits`.
std::uint32_t presented_type_bits(const MemoryModel& model, std::uint32_t real_bits);

struct FreeDeleter {
  void operator()(void* p) const;
};

// One VkDeviceMemory. While mapped, the application holds `shadow`, the layer `real` (the driver's
// mapping of the same range); bytes move between them only on flush and invalidate.
struct Allocation {
  VkDeviceSize size = 0;
  bool host_visible = false;   // as presented
  bool real_coherent = true;   // the backing type: when not, the layer flushes and invalidates it too
  std::byte* real = nullptr;
  std::unique_ptr<std::byte, FreeDeleter> shadow_block;  // 256-byte aligned, holds `shadow`
  std::byte* shadow = nullptr;
  VkDeviceSize map_offset = 0, map_size = 0;
};

struct DeviceState {
  VkDevice handle = VK_NULL_HANDLE;
  DeviceDispatch next;
  MemoryModel memory;
  Counters counters;
  std::unordered_map<VkDeviceMemory, Allocation> allocations;
  std::atomic<bool> lost{false};  // a fault made it lost (faults.cpp)
};

// The faults of $POND_DISCRETE_GPU_FAULT (faults.cpp says the syntax).
enum class FaultKind { device_lost, out_of_device_memory, out_of_host_memory };
// Whether the variable is well formed; if not, says what is wrong on stderr (vkCreateDevice then
// fails with VK_ERROR_INITIALIZATION_FAILED).
bool fault_plan_ok();
// Counts a submission on `device`: true when it must fail with VK_ERROR_DEVICE_LOST (the device
// was lost before, or this is the planned submission; then it waits for the real queue first).
bool submit_fault(DeviceState& d);
// Counts an allocation: VK_SUCCESS, or the error planned for it.
VkResult allocation_fault();

// Every instance and device this layer has created, by dispatch key, under one mutex. The layer
// holds it while calling the next layer's memory functions: nothing below calls back up.
struct Registry {
  std::mutex mutex;
  std::unordered_map<void*, InstanceDispatch> instances;
  std::unordered_map<void*, std::unique_ptr<DeviceState>> devices;
};
Registry& registry();
// The instance behind `key` (an instance's or physical device's), copied under the lock.
InstanceDispatch instance_dispatch(void* key);
// The device's state; the caller holds registry().mutex.
DeviceState& device_state(VkDevice device);

// The device's state for a device-level handle (a device, queue or command buffer share the key);
// null when the layer did not create it. Takes the lock; the state lives until vkDestroyDevice.
DeviceState* find_device_state(void* key);

// Intercepted commands (the loader reaches them through vkGet*ProcAddr in layer.cpp).
VKAPI_ATTR void VKAPI_CALL get_physical_device_properties(VkPhysicalDevice, VkPhysicalDeviceProperties*);
VKAPI_ATTR void VKAPI_CALL get_physical_device_properties2(VkPhysicalDevice, VkPhysicalDeviceProperties2*);
VKAPI_ATTR void VKAPI_CALL get_physical_device_features(VkPhysicalDevice, VkPhysicalDeviceFeatures*);
VKAPI_ATTR void VKAPI_CALL get_physical_device_features2(VkPhysicalDevice, VkPhysicalDeviceFeatures2*);
VKAPI_ATTR void VKAPI_CALL get_physical_device_memory_properties(VkPhysicalDevice,
                                                                 VkPhysicalDeviceMemoryProperties*);
VKAPI_ATTR void VKAPI_CALL get_physical_device_memory_properties2(VkPhysicalDevice,
                                                                  VkPhysicalDeviceMemoryProperties2*);
// POND_DISCRETE_GPU_NO_TIMESTAMPS=1 (timestamps.cpp): no timestamps on the presented device.
bool hides_timestamps();
VKAPI_ATTR void VKAPI_CALL get_physical_device_queue_family_properties(VkPhysicalDevice, std::uint32_t*,
                                                                       VkQueueFamilyProperties*);
VKAPI_ATTR void VKAPI_CALL get_physical_device_queue_family_properties2(VkPhysicalDevice, std::uint32_t*,
                                                                        VkQueueFamilyProperties2*);
// Whether vkCreateDevice asks for a feature the presented device lacks (shaderInt64 and the 64-bit
// atomics); says which on stderr.
bool requests_hidden_feature(const VkDeviceCreateInfo& info);

VKAPI_ATTR VkResult VKAPI_CALL allocate_memory(VkDevice, const VkMemoryAllocateInfo*, const VkAllocationCallbacks*,
                                               VkDeviceMemory*);
VKAPI_ATTR void VKAPI_CALL free_memory(VkDevice, VkDeviceMemory, const VkAllocationCallbacks*);
VKAPI_ATTR VkResult VKAPI_CALL map_memory(VkDevice, VkDeviceMemory, VkDeviceSize offset, VkDeviceSize size,
                                          VkMemoryMapFlags, void** data);
VKAPI_ATTR void VKAPI_CALL unmap_memory(VkDevice, VkDeviceMemory);
VKAPI_ATTR VkResult VKAPI_CALL flush_mapped_memory_ranges(VkDevice, std::uint32_t count, const VkMappedMemoryRange*);
VKAPI_ATTR VkResult VKAPI_CALL invalidate_mapped_memory_ranges(VkDevice, std::uint32_t count,
                                                               const VkMappedMemoryRange*);
VKAPI_ATTR void VKAPI_CALL get_buffer_memory_requirements(VkDevice, VkBuffer, VkMemoryRequirements*);
VKAPI_ATTR void VKAPI_CALL get_image_memory_requirements(VkDevice, VkImage, VkMemoryRequirements*);
VKAPI_ATTR void VKAPI_CALL get_buffer_memory_requirements2(VkDevice, const VkBufferMemoryRequirementsInfo2*,
                                                           VkMemoryRequirements2*);
VKAPI_ATTR void VKAPI_CALL get_image_memory_requirements2(VkDevice, const VkImageMemoryRequirementsInfo2*,
                                                          VkMemoryRequirements2*);
VKAPI_ATTR void VKAPI_CALL get_device_buffer_memory_requirements(VkDevice, const VkDeviceBufferMemoryRequirements*,
                                                                 VkMemoryRequirements2*);
VKAPI_ATTR void VKAPI_CALL get_device_image_memory_requirements(VkDevice, const VkDeviceImageMemoryRequirements*,
                                                                VkMemoryRequirements2*);
VKAPI_ATTR VkResult VKAPI_CALL queue_submit(VkQueue, std::uint32_t count, const VkSubmitInfo*, VkFence);
VKAPI_ATTR VkResult VKAPI_CALL queue_submit2(VkQueue, std::uint32_t count, const VkSubmitInfo2*, VkFence);
VKAPI_ATTR VkResult VKAPI_CALL wait_for_fences(VkDevice, std::uint32_t count, const VkFence*, VkBool32 wait_all,
                                               std::uint64_t timeout);
VKAPI_ATTR VkResult VKAPI_CALL queue_wait_idle(VkQueue);
VKAPI_ATTR VkResult VKAPI_CALL device_wait_idle(VkDevice);
VKAPI_ATTR VkResult VKAPI_CALL wait_semaphores(VkDevice, const VkSemaphoreWaitInfo*, std::uint64_t timeout);
VKAPI_ATTR VkResult VKAPI_CALL get_fence_status(VkDevice, VkFence);
VKAPI_ATTR VkResult VKAPI_CALL acquire_next_image(VkDevice, VkSwapchainKHR, std::uint64_t timeout, VkSemaphore, VkFence,
                                                  std::uint32_t* index);
VKAPI_ATTR VkResult VKAPI_CALL queue_present(VkQueue, const VkPresentInfoKHR*);
VKAPI_ATTR VkResult VKAPI_CALL get_query_pool_results(VkDevice, VkQueryPool, std::uint32_t first, std::uint32_t count,
                                                      std::size_t size, void* data, VkDeviceSize stride,
                                                      VkQueryResultFlags flags);
}  // namespace pond::layer
