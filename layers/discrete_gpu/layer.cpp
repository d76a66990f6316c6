// The loader interface of VK_LAYER_POND_discrete_gpu: version negotiation, vkGet*ProcAddr, and the
// creation and destruction of instances and devices, which record the next layer's functions.
#include <cstdarg>
#include <cstdio>
#include <cstring>

#include "layer.h"

namespace pond::layer {

void report(const char* format, ...) {
  char line[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  std::fprintf(stderr, "%s: %s\n", kLayerName, line);
}

Registry& registry() {
  static Registry r;
  return r;
}

InstanceDispatch instance_dispatch(void* key) {
  std::lock_guard lock(registry().mutex);
  const auto it = registry().instances.find(key);
  return it == registry().instances.end() ? InstanceDispatch{} : it->second;
}

DeviceState& device_state(VkDevice device) {
  return *registry().devices.at(dispatch_key(device));
}

namespace {

template <typename F>
PFN_vkVoidFunction as_void(F f) {
  return reinterpret_cast<PFN_vkVoidFunction>(f);
}

template <typename F>
F load(PFN_vkGetInstanceProcAddr gipa, VkInstance instance, const char* name) {
  return reinterpret_cast<F>(gipa(instance, name));
}

// The core command, or its KHR alias where only the extension provides it.
template <typename F>
F load(PFN_vkGetDeviceProcAddr gdpa, VkDevice device, const char* name, const char* khr_alias = nullptr) {
  PFN_vkVoidFunction f = gdpa(device, name);
  if (!f && khr_alias) f = gdpa(device, khr_alias);
  return reinterpret_cast<F>(f);
}

// The loader's link in a create-info chain: which layer comes next.
template <typename LinkInfo>
LinkInfo* find_link(const void* next, VkStructureType type) {
  for (auto* s = static_cast<const VkBaseInStructure*>(next); s; s = s->pNext) {
    auto* info = reinterpret_cast<const LinkInfo*>(s);
    if (s->sType == type && info->function == VK_LAYER_LINK_INFO) return const_cast<LinkInfo*>(info);
  }
  return nullptr;
}

VKAPI_ATTR VkResult VKAPI_CALL create_instance(const VkInstanceCreateInfo* info, const VkAllocationCallbacks* allocator,
                                               VkInstance* instance) {
  auto* link = find_link<VkLayerInstanceCreateInfo>(info->pNext, VK_STRUCTURE_TYPE_LOADER_INSTANCE_CREATE_INFO);
  if (!link || !link->u.pLayerInfo) return VK_ERROR_INITIALIZATION_FAILED;
  const PFN_vkGetInstanceProcAddr gipa = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
  link->u.pLayerInfo = link->u.pLayerInfo->pNext;  // the next layer reads its own link
  const auto next_create = load<PFN_vkCreateInstance>(gipa, VK_NULL_HANDLE, "vkCreateInstance");
  if (!next_create) return VK_ERROR_INITIALIZATION_FAILED;
  const VkResult result = next_create(info, allocator, instance);
  if (result != VK_SUCCESS) return result;

  const VkInstance in = *instance;
  InstanceDispatch d{
      .instance = in,
      .get_proc_addr = gipa,
      .destroy_instance = load<PFN_vkDestroyInstance>(gipa, in, "vkDestroyInstance"),
      .get_properties = load<PFN_vkGetPhysicalDeviceProperties>(gipa, in, "vkGetPhysicalDeviceProperties"),
      .get_properties2 = load<PFN_vkGetPhysicalDeviceProperties2>(gipa, in, "vkGetPhysicalDeviceProperties2"),
      .get_features = load<PFN_vkGetPhysicalDeviceFeatures>(gipa, in, "vkGetPhysicalDeviceFeatures"),
      .get_features2 = load<PFN_vkGetPhysicalDeviceFeatures2>(gipa, in, "vkGetPhysicalDeviceFeatures2"),
      .get_memory_properties =
          load<PFN_vkGetPhysicalDeviceMemoryProperties>(gipa, in, "vkGetPhysicalDeviceMemoryProperties"),
      .get_memory_properties2 =
          load<PFN_vkGetPhysicalDeviceMemoryProperties2>(gipa, in, "vkGetPhysicalDeviceMemoryProperties2"),
      .get_queue_families =
          load<PFN_vkGetPhysicalDeviceQueueFamilyProperties>(gipa, in, "vkGetPhysicalDeviceQueueFamilyProperties"),
      .get_queue_families2 =
          load<PFN_vkGetPhysicalDeviceQueueFamilyProperties2>(gipa, in, "vkGetPhysicalDeviceQueueFamilyProperties2")};
  // A Vulkan 1.0 instance has the *2 queries only from VK_KHR_get_physical_device_properties2.
  if (!d.get_properties2)
    d.get_properties2 = load<PFN_vkGetPhysicalDeviceProperties2>(gipa, in, "vkGetPhysicalDeviceProperties2KHR");
  if (!d.get_features2)
    d.get_features2 = load<PFN_vkGetPhysicalDeviceFeatures2>(gipa, in, "vkGetPhysicalDeviceFeatures2KHR");
  if (!d.get_memory_properties2)
    d.get_memory_properties2 =
        load<PFN_vkGetPhysicalDeviceMemoryProperties2>(gipa, in, "vkGetPhysicalDeviceMemoryProperties2KHR");
  if (!d.get_queue_families2)
    d.get_queue_families2 =
        load<PFN_vkGetPhysicalDeviceQueueFamilyProperties2>(gipa, in, "vkGetPhysicalDeviceQueueFamilyProperties2KHR");
  std::lock_guard lock(registry().mutex);
  registry().instances[dispatch_key(in)] = d;
  return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL destroy_instance(VkInstance instance, const VkAllocationCallbacks* allocator) {
  if (!instance) return;
  const InstanceDispatch d = instance_dispatch(dispatch_key(instance));
  {
    std::lock_guard lock(registry().mutex);
    registry().instances.erase(dispatch_key(instance));
  }
  if (d.destroy_instance) d.destroy_instance(instance, allocator);
}

VKAPI_ATTR VkResult VKAPI_CALL create_device(VkPhysicalDevice physical, const VkDeviceCreateInfo* info,
                                             const VkAllocationCallbacks* allocator, VkDevice* device) {
  // Honest refusal: the presented device has no shaderInt64, so asking for it fails as on such a GPU.
  if (requests_hidden_feature(*info)) return VK_ERROR_FEATURE_NOT_PRESENT;
  if (!fault_plan_ok()) return VK_ERROR_INITIALIZATION_FAILED;
  auto* link = find_link<VkLayerDeviceCreateInfo>(info->pNext, VK_STRUCTURE_TYPE_LOADER_DEVICE_CREATE_INFO);
  const InstanceDispatch inst = instance_dispatch(dispatch_key(physical));
  if (!link || !link->u.pLayerInfo || !inst.instance) return VK_ERROR_INITIALIZATION_FAILED;
  const PFN_vkGetInstanceProcAddr gipa = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
  const PFN_vkGetDeviceProcAddr gdpa = link->u.pLayerInfo->pfnNextGetDeviceProcAddr;
  link->u.pLayerInfo = link->u.pLayerInfo->pNext;
  const auto next_create = load<PFN_vkCreateDevice>(gipa, inst.instance, "vkCreateDevice");
  if (!next_create) return VK_ERROR_INITIALIZATION_FAILED;
  const VkResult result = next_create(physical, info, allocator, device);
  if (result != VK_SUCCESS) return result;

  const VkDevice dev = *device;
  auto state = std::make_unique<DeviceState>();
  state->handle = dev;
  state->next = DeviceDispatch{
      .get_proc_addr = gdpa,
      .destroy_device = load<PFN_vkDestroyDevice>(gdpa, dev, "vkDestroyDevice"),
      .allocate_memory = load<PFN_vkAllocateMemory>(gdpa, dev, "vkAllocateMemory"),
      .free_memory = load<PFN_vkFreeMemory>(gdpa, dev, "vkFreeMemory"),
      .map_memory = load<PFN_vkMapMemory>(gdpa, dev, "vkMapMemory"),
      .unmap_memory = load<PFN_vkUnmapMemory>(gdpa, dev, "vkUnmapMemory"),
      .flush_ranges = load<PFN_vkFlushMappedMemoryRanges>(gdpa, dev, "vkFlushMappedMemoryRanges"),
      .invalidate_ranges = load<PFN_vkInvalidateMappedMemoryRanges>(gdpa, dev, "vkInvalidateMappedMemoryRanges"),
      .buffer_requirements = load<PFN_vkGetBufferMemoryRequirements>(gdpa, dev, "vkGetBufferMemoryRequirements"),
      .image_requirements = load<PFN_vkGetImageMemoryRequirements>(gdpa, dev, "vkGetImageMemoryRequirements"),
      .buffer_requirements2 = load<PFN_vkGetBufferMemoryRequirements2>(
          gdpa, dev, "vkGetBufferMemoryRequirements2", "vkGetBufferMemoryRequirements2KHR"),
      .image_requirements2 = load<PFN_vkGetImageMemoryRequirements2>(
          gdpa, dev, "vkGetImageMemoryRequirements2", "vkGetImageMemoryRequirements2KHR"),
      .device_buffer_requirements = load<PFN_vkGetDeviceBufferMemoryRequirements>(
          gdpa, dev, "vkGetDeviceBufferMemoryRequirements", "vkGetDeviceBufferMemoryRequirementsKHR"),
      .device_image_requirements = load<PFN_vkGetDeviceImageMemoryRequirements>(
          gdpa, dev, "vkGetDeviceImageMemoryRequirements", "vkGetDeviceImageMemoryRequirementsKHR"),
      .queue_submit = load<PFN_vkQueueSubmit>(gdpa, dev, "vkQueueSubmit"),
      .queue_submit2 = load<PFN_vkQueueSubmit2>(gdpa, dev, "vkQueueSubmit2", "vkQueueSubmit2KHR"),
      .wait_for_fences = load<PFN_vkWaitForFences>(gdpa, dev, "vkWaitForFences"),
      .queue_wait_idle = load<PFN_vkQueueWaitIdle>(gdpa, dev, "vkQueueWaitIdle"),
      .device_wait_idle = load<PFN_vkDeviceWaitIdle>(gdpa, dev, "vkDeviceWaitIdle"),
      .wait_semaphores = load<PFN_vkWaitSemaphores>(gdpa, dev, "vkWaitSemaphores", "vkWaitSemaphoresKHR"),
      .get_fence_status = load<PFN_vkGetFenceStatus>(gdpa, dev, "vkGetFenceStatus"),
      .acquire_next_image = load<PFN_vkAcquireNextImageKHR>(gdpa, dev, "vkAcquireNextImageKHR"),
      .queue_present = load<PFN_vkQueuePresentKHR>(gdpa, dev, "vkQueuePresentKHR"),
      .get_query_pool_results = load<PFN_vkGetQueryPoolResults>(gdpa, dev, "vkGetQueryPoolResults")};
  VkPhysicalDeviceMemoryProperties real{};
  inst.get_memory_properties(physical, &real);
  state->memory = make_memory_model(real);
  std::lock_guard lock(registry().mutex);
  registry().devices[dispatch_key(dev)] = std::move(state);
  return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL destroy_device(VkDevice device, const VkAllocationCallbacks* allocator) {
  if (!device) return;
  std::unique_ptr<DeviceState> state;
  {
    std::lock_guard lock(registry().mutex);
    const auto it = registry().devices.find(dispatch_key(device));
    if (it == registry().devices.end()) return;
    state = std::move(it->second);
    registry().devices.erase(it);
  }
  state->next.destroy_device(device, allocator);  // shadows of still-mapped memory go with `state`
  write_counters(state->counters);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_device_proc_addr(VkDevice device, const char* name);
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_instance_proc_addr(VkInstance instance, const char* name);

struct Entry {
  const char* name;
  PFN_vkVoidFunction function;
};

const Entry kInstanceCommands[] = {
    {"vkGetInstanceProcAddr", as_void(get_instance_proc_addr)},
    {"vkCreateInstance", as_void(create_instance)},
    {"vkDestroyInstance", as_void(destroy_instance)},
    {"vkCreateDevice", as_void(create_device)},
    {"vkGetPhysicalDeviceProperties", as_void(get_physical_device_properties)},
    {"vkGetPhysicalDeviceProperties2", as_void(get_physical_device_properties2)},
    {"vkGetPhysicalDeviceProperties2KHR", as_void(get_physical_device_properties2)},
    {"vkGetPhysicalDeviceFeatures", as_void(get_physical_device_features)},
    {"vkGetPhysicalDeviceFeatures2", as_void(get_physical_device_features2)},
    {"vkGetPhysicalDeviceFeatures2KHR", as_void(get_physical_device_features2)},
    {"vkGetPhysicalDeviceMemoryProperties", as_void(get_physical_device_memory_properties)},
    {"vkGetPhysicalDeviceMemoryProperties2", as_void(get_physical_device_memory_properties2)},
    {"vkGetPhysicalDeviceMemoryProperties2KHR", as_void(get_physical_device_memory_properties2)},
    {"vkGetPhysicalDeviceQueueFamilyProperties", as_void(get_physical_device_queue_family_properties)},
    {"vkGetPhysicalDeviceQueueFamilyProperties2", as_void(get_physical_device_queue_family_properties2)},
    {"vkGetPhysicalDeviceQueueFamilyProperties2KHR", as_void(get_physical_device_queue_family_properties2)},
};

const Entry kDeviceCommands[] = {
    {"vkGetDeviceProcAddr", as_void(get_device_proc_addr)},
    {"vkDestroyDevice", as_void(destroy_device)},
    {"vkAllocateMemory", as_void(allocate_memory)},
    {"vkFreeMemory", as_void(free_memory)},
    {"vkMapMemory", as_void(map_memory)},
    {"vkUnmapMemory", as_void(unmap_memory)},
    {"vkFlushMappedMemoryRanges", as_void(flush_mapped_memory_ranges)},
    {"vkInvalidateMappedMemoryRanges", as_void(invalidate_mapped_memory_ranges)},
    {"vkGetBufferMemoryRequirements", as_void(get_buffer_memory_requirements)},
    {"vkGetImageMemoryRequirements", as_void(get_image_memory_requirements)},
    {"vkGetBufferMemoryRequirements2", as_void(get_buffer_memory_requirements2)},
    {"vkGetBufferMemoryRequirements2KHR", as_void(get_buffer_memory_requirements2)},
    {"vkGetImageMemoryRequirements2", as_void(get_image_memory_requirements2)},
    {"vkGetImageMemoryRequirements2KHR", as_void(get_image_memory_requirements2)},
    {"vkGetDeviceBufferMemoryRequirements", as_void(get_device_buffer_memory_requirements)},
    {"vkGetDeviceBufferMemoryRequirementsKHR", as_void(get_device_buffer_memory_requirements)},
    {"vkGetDeviceImageMemoryRequirements", as_void(get_device_image_memory_requirements)},
    {"vkGetDeviceImageMemoryRequirementsKHR", as_void(get_device_image_memory_requirements)},
    {"vkQueueSubmit", as_void(queue_submit)},
    {"vkQueueSubmit2", as_void(queue_submit2)},
    {"vkQueueSubmit2KHR", as_void(queue_submit2)},
    {"vkWaitForFences", as_void(wait_for_fences)},
    {"vkQueueWaitIdle", as_void(queue_wait_idle)},
    {"vkDeviceWaitIdle", as_void(device_wait_idle)},
    {"vkWaitSemaphores", as_void(wait_semaphores)},
    {"vkWaitSemaphoresKHR", as_void(wait_semaphores)},
    {"vkGetFenceStatus", as_void(get_fence_status)},
    {"vkAcquireNextImageKHR", as_void(acquire_next_image)},
    {"vkQueuePresentKHR", as_void(queue_present)},
    {"vkGetQueryPoolResults", as_void(get_query_pool_results)},
};

template <std::size_t N>
PFN_vkVoidFunction find(const Entry (&table)[N], const char* name) {
  for (const Entry& e : table)
    if (std::strcmp(e.name, name) == 0) return e.function;
  return nullptr;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_device_proc_addr(VkDevice device, const char* name) {
  if (!device || !name) return nullptr;
  PFN_vkGetDeviceProcAddr next = nullptr;
  {
    std::lock_guard lock(registry().mutex);
    const auto it = registry().devices.find(dispatch_key(device));
    if (it == registry().devices.end()) return nullptr;
    next = it->second->next.get_proc_addr;
  }
  const PFN_vkVoidFunction below = next(device, name);
  // An intercepted command the device does not have (an extension not enabled) stays absent.
  if (const PFN_vkVoidFunction ours = find(kDeviceCommands, name)) return below ? ours : nullptr;
  return below;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_instance_proc_addr(VkInstance instance, const char* name) {
  if (!name) return nullptr;
  if (const PFN_vkVoidFunction ours = find(kInstanceCommands, name)) return ours;
  if (const PFN_vkVoidFunction ours = find(kDeviceCommands, name)) return ours;
  if (!instance) return nullptr;
  const InstanceDispatch d = instance_dispatch(dispatch_key(instance));
  return d.get_proc_addr ? d.get_proc_addr(instance, name) : nullptr;
}

}  // namespace
}  // namespace pond::layer

// The exported entry points (all else is hidden): the loader negotiates interface version 2 and
// then calls the layer only through the two functions it hands back.
extern "C" {

__attribute__((visibility("default"))) VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL
vkGetInstanceProcAddr(VkInstance instance, const char* name) {
  return pond::layer::get_instance_proc_addr(instance, name);
}

__attribute__((visibility("default"))) VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL
vkGetDeviceProcAddr(VkDevice device, const char* name) {
  return pond::layer::get_device_proc_addr(device, name);
}

__attribute__((visibility("default"))) VKAPI_ATTR VkResult VKAPI_CALL
vkNegotiateLoaderLayerInterfaceVersion(VkNegotiateLayerInterface* version) {
  if (!version || version->sType != LAYER_NEGOTIATE_INTERFACE_STRUCT) return VK_ERROR_INITIALIZATION_FAILED;
  if (version->loaderLayerInterfaceVersion < 2) return VK_ERROR_INITIALIZATION_FAILED;
  version->loaderLayerInterfaceVersion = 2;
  version->pfnGetInstanceProcAddr = pond::layer::get_instance_proc_addr;
  version->pfnGetDeviceProcAddr = pond::layer::get_device_proc_addr;
  version->pfnGetPhysicalDeviceProcAddr = nullptr;  // no physical-device commands of unknown extensions
  return VK_SUCCESS;
}

}  // extern "C"
