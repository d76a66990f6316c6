// The memory of the presented device: device-local memory the host cannot map, and host-visible
// memory that is not coherent, made real with a shadow copy per mapping.
//
// Every real type that is both DEVICE_LOCAL and HOST_VISIBLE becomes two presented types: one
// DEVICE_LOCAL only (on the real heap), one HOST_VISIBLE (+ HOST_CACHED if real) without
// HOST_COHERENT, on a second heap without DEVICE_LOCAL. Both allocate from the same real type.
// Other host-visible types lose HOST_COHERENT. On lavapipe: type 0 = DEVICE_LOCAL on heap 0,
// type 1 = HOST_VISIBLE | HOST_CACHED on heap 1.
//
// vkMapMemory hands out a shadow buffer filled with kPoison, not the memory: host writes reach
// the device only through vkFlushMappedMemoryRanges (shadow -> memory) and device writes reach the
// host only through vkInvalidateMappedMemoryRanges (memory -> shadow). A range must start on a
// 256-byte atom and end on one or at the end of the allocation, as on hardware with that atom.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "layer.h"

namespace pond::layer {

void FreeDeleter::operator()(void* p) const { std::free(p); }

namespace {

constexpr VkMemoryPropertyFlags kHostFlags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                             VK_MEMORY_PROPERTY_HOST_COHERENT_BIT |
                                             VK_MEMORY_PROPERTY_HOST_CACHED_BIT;

// What a mapped pointer reads before the first invalidate: all ones, a NaN in every float and an
// impossible index in every uint, so a missing invalidate shows.
constexpr unsigned char kPoison = 0xFF;

bool is_host_visible(VkMemoryPropertyFlags f) { return (f & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) != 0; }
bool is_split(VkMemoryPropertyFlags f) {
  return (f & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) && is_host_visible(f);
}

void translate_bits(const MemoryModel& model, VkMemoryRequirements& r) {
  r.memoryTypeBits = presented_type_bits(model, r.memoryTypeBits);
}

// A flush or invalidate range that passed check_range: [begin, end) in bytes from the start of
// the allocation. check_range refuses a range with a line on stderr and returns false.
struct Span {
  Allocation* allocation;
  VkDeviceSize begin, end;
};

bool check_range(DeviceState& state, const VkMappedMemoryRange& range, const char* command, Span& span) {
  const auto it = state.allocations.find(range.memory);
  if (it == state.allocations.end() || !it->second.shadow) {
    report("%s: the memory is not mapped; refused with VK_ERROR_UNKNOWN", command);
    return false;
  }
  Allocation& a = it->second;
  const VkDeviceSize map_end = a.map_offset + a.map_size;
  const VkDeviceSize end = range.size == VK_WHOLE_SIZE ? map_end : range.offset + range.size;
  const char* problem = nullptr;
  if (range.offset % kAtomSize != 0)
    problem = "offset is not a multiple of nonCoherentAtomSize (256)";
  else if (range.size != VK_WHOLE_SIZE && range.size % kAtomSize != 0 && end != a.size)
    problem = "size is not a multiple of nonCoherentAtomSize (256) and does not reach the end of the allocation";
  else if (range.size == VK_WHOLE_SIZE && map_end % kAtomSize != 0 && map_end != a.size)
    problem = "VK_WHOLE_SIZE, but the mapping ends neither on a 256-byte atom nor at the end of the allocation";
  else if (range.offset < a.map_offset || range.offset > map_end || end > map_end)
    problem = "the range is not inside the mapped range";
  if (problem) {
    report("%s: offset %llu size %llu: %s; refused with VK_ERROR_UNKNOWN", command,
           static_cast<unsigned long long>(range.offset), static_cast<unsigned long long>(range.size), problem);
    return false;
  }
  span = Span{&a, range.offset, end};
  return true;
}

// Checks every range before touching any, so a refused call has no effect.
bool check_ranges(DeviceState& state, std::uint32_t count, const VkMappedMemoryRange* ranges, const char* command,
                  std::vector<Span>& spans) {
  spans.resize(count);
  for (std::uint32_t i = 0; i < count; ++i)
    if (!check_range(state, ranges[i], command, spans[i])) return false;
  return true;
}

bool any_real_non_coherent(const std::vector<Span>& spans) {
  return std::any_of(spans.begin(), spans.end(), [](const Span& s) { return !s.allocation->real_coherent; });
}

}  // namespace

MemoryModel make_memory_model(const VkPhysicalDeviceMemoryProperties& real) {
  MemoryModel m;
  m.real = real;
  VkPhysicalDeviceMemoryProperties& p = m.presented;
  p.memoryHeapCount = real.memoryHeapCount;
  std::copy_n(real.memoryHeaps, real.memoryHeapCount, p.memoryHeaps);
  auto add_type = [&](VkMemoryPropertyFlags flags, std::uint32_t heap, std::uint32_t real_type) {
    if (p.memoryTypeCount == VK_MAX_MEMORY_TYPES) return;
    m.real_type[p.memoryTypeCount] = real_type;
    p.memoryTypes[p.memoryTypeCount++] = VkMemoryType{flags, heap};
  };
  // First every type's device side (or the type itself, coherence removed), then the host sides
  // of the split types: a type whose flags are a subset of another's comes first, as Vulkan asks.
  for (std::uint32_t t = 0; t < real.memoryTypeCount; ++t) {
    const VkMemoryType& type = real.memoryTypes[t];
    const VkMemoryPropertyFlags flags = is_split(type.propertyFlags)
                                            ? type.propertyFlags & ~kHostFlags
                                            : type.propertyFlags & ~VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    add_type(flags, type.heapIndex, t);
  }
  std::uint32_t host_heap[VK_MAX_MEMORY_HEAPS];
  std::fill_n(host_heap, VK_MAX_MEMORY_HEAPS, VK_MAX_MEMORY_HEAPS);
  for (std::uint32_t t = 0; t < real.memoryTypeCount; ++t) {
    const VkMemoryType& type = real.memoryTypes[t];
    if (!is_split(type.propertyFlags)) continue;
    // The host side lives on its own heap, as system memory does on a discrete GPU; it reports the
    // real heap's size (both heaps are the same memory).
    std::uint32_t& heap = host_heap[type.heapIndex];
    if (heap == VK_MAX_MEMORY_HEAPS && p.memoryHeapCount < VK_MAX_MEMORY_HEAPS) {
      heap = p.memoryHeapCount++;
      p.memoryHeaps[heap] = VkMemoryHeap{real.memoryHeaps[type.heapIndex].size, 0};
    }
    if (heap == VK_MAX_MEMORY_HEAPS) continue;
    const VkMemoryPropertyFlags host = type.propertyFlags & (VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                             VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
    add_type(host, heap, t);
  }
  return m;
}

std::uint32_t presented_type_bits(const MemoryModel& model, std::uint32_t real_bits) {
  std::uint32_t bits = 0;
  for (std::uint32_t t = 0; t < model.presented.memoryTypeCount; ++t)
    if (real_bits & (1u << model.real_type[t])) bits |= 1u << t;
  return bits;
}

// Memory properties: stateless, rebuilt from the real answer on each query. (Memory budgets,
// VK_EXT_memory_budget, are per real heap and not rewritten: lavapipe does not offer them.)
VKAPI_ATTR void VKAPI_CALL get_physical_device_memory_properties(VkPhysicalDevice physical,
                                                                 VkPhysicalDeviceMemoryProperties* properties) {
  instance_dispatch(dispatch_key(physical)).get_memory_properties(physical, properties);
  *properties = make_memory_model(*properties).presented;
}

VKAPI_ATTR void VKAPI_CALL get_physical_device_memory_properties2(VkPhysicalDevice physical,
                                                                  VkPhysicalDeviceMemoryProperties2* properties) {
  instance_dispatch(dispatch_key(physical)).get_memory_properties2(physical, properties);
  properties->memoryProperties = make_memory_model(properties->memoryProperties).presented;
}

VKAPI_ATTR void VKAPI_CALL get_buffer_memory_requirements(VkDevice device, VkBuffer buffer,
                                                          VkMemoryRequirements* requirements) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  d.next.buffer_requirements(device, buffer, requirements);
  translate_bits(d.memory, *requirements);
}

VKAPI_ATTR void VKAPI_CALL get_image_memory_requirements(VkDevice device, VkImage image,
                                                         VkMemoryRequirements* requirements) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  d.next.image_requirements(device, image, requirements);
  translate_bits(d.memory, *requirements);
}

VKAPI_ATTR void VKAPI_CALL get_buffer_memory_requirements2(VkDevice device, const VkBufferMemoryRequirementsInfo2* info,
                                                           VkMemoryRequirements2* requirements) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  d.next.buffer_requirements2(device, info, requirements);
  translate_bits(d.memory, requirements->memoryRequirements);
}

VKAPI_ATTR void VKAPI_CALL get_image_memory_requirements2(VkDevice device, const VkImageMemoryRequirementsInfo2* info,
                                                          VkMemoryRequirements2* requirements) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  d.next.image_requirements2(device, info, requirements);
  translate_bits(d.memory, requirements->memoryRequirements);
}

VKAPI_ATTR void VKAPI_CALL get_device_buffer_memory_requirements(VkDevice device,
                                                                 const VkDeviceBufferMemoryRequirements* info,
                                                                 VkMemoryRequirements2* requirements) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  d.next.device_buffer_requirements(device, info, requirements);
  translate_bits(d.memory, requirements->memoryRequirements);
}

VKAPI_ATTR void VKAPI_CALL get_device_image_memory_requirements(VkDevice device,
                                                                const VkDeviceImageMemoryRequirements* info,
                                                                VkMemoryRequirements2* requirements) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  d.next.device_image_requirements(device, info, requirements);
  translate_bits(d.memory, requirements->memoryRequirements);
}

VKAPI_ATTR VkResult VKAPI_CALL allocate_memory(VkDevice device, const VkMemoryAllocateInfo* info,
                                               const VkAllocationCallbacks* allocator, VkDeviceMemory* memory) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  const VkPhysicalDeviceMemoryProperties& presented = d.memory.presented;
  if (info->memoryTypeIndex >= presented.memoryTypeCount) {
    report("vkAllocateMemory: memory type %u does not exist (the device has %u); refused with VK_ERROR_UNKNOWN",
           info->memoryTypeIndex, presented.memoryTypeCount);
    return VK_ERROR_UNKNOWN;
  }
  ++d.counters.allocations;
  if (const VkResult fault = allocation_fault(); fault != VK_SUCCESS) return fault;
  VkMemoryAllocateInfo real_info = *info;
  real_info.memoryTypeIndex = d.memory.real_type[info->memoryTypeIndex];
  const VkResult result = d.next.allocate_memory(device, &real_info, allocator, memory);
  if (result != VK_SUCCESS) return result;
  Allocation& a = d.allocations[*memory];
  a.size = info->allocationSize;
  a.host_visible = is_host_visible(presented.memoryTypes[info->memoryTypeIndex].propertyFlags);
  a.real_coherent = (d.memory.real.memoryTypes[real_info.memoryTypeIndex].propertyFlags &
                     VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
  return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL free_memory(VkDevice device, VkDeviceMemory memory, const VkAllocationCallbacks* allocator) {
  if (!memory) return;
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  d.allocations.erase(memory);  // freeing unmaps: the shadow goes too
  d.next.free_memory(device, memory, allocator);
}

VKAPI_ATTR VkResult VKAPI_CALL map_memory(VkDevice device, VkDeviceMemory memory, VkDeviceSize offset,
                                          VkDeviceSize size, VkMemoryMapFlags flags, void** data) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  const auto it = d.allocations.find(memory);
  if (it == d.allocations.end()) return d.next.map_memory(device, memory, offset, size, flags, data);
  Allocation& a = it->second;
  if (!a.host_visible) {
    report("vkMapMemory: the memory type is DEVICE_LOCAL, not HOST_VISIBLE (copy through a staging buffer); "
           "refused with VK_ERROR_MEMORY_MAP_FAILED");
    return VK_ERROR_MEMORY_MAP_FAILED;
  }
  if (a.shadow) {
    report("vkMapMemory: the memory is already mapped; refused with VK_ERROR_MEMORY_MAP_FAILED");
    return VK_ERROR_MEMORY_MAP_FAILED;
  }
  if (offset >= a.size || (size != VK_WHOLE_SIZE && (size == 0 || size > a.size - offset))) {
    report("vkMapMemory: offset %llu size %llu is outside the allocation of %llu bytes; refused with "
           "VK_ERROR_MEMORY_MAP_FAILED",
           static_cast<unsigned long long>(offset), static_cast<unsigned long long>(size),
           static_cast<unsigned long long>(a.size));
    return VK_ERROR_MEMORY_MAP_FAILED;
  }
  void* real = nullptr;
  const VkResult result = d.next.map_memory(device, memory, offset, size, flags, &real);
  if (result != VK_SUCCESS) return result;
  const VkDeviceSize length = size == VK_WHOLE_SIZE ? a.size - offset : size;
  // The pointer minus the offset stays 256-byte aligned (minMemoryMapAlignment is 64), as when
  // the whole allocation is mapped at an aligned address.
  const std::size_t lead = static_cast<std::size_t>(offset % kAtomSize);
  const std::size_t block = (lead + static_cast<std::size_t>(length) + kAtomSize - 1) / kAtomSize * kAtomSize;
  a.shadow_block.reset(static_cast<std::byte*>(std::aligned_alloc(kAtomSize, block)));
  if (!a.shadow_block) {
    d.next.unmap_memory(device, memory);
    return VK_ERROR_OUT_OF_HOST_MEMORY;
  }
  std::memset(a.shadow_block.get(), kPoison, block);
  a.real = static_cast<std::byte*>(real);
  a.shadow = a.shadow_block.get() + lead;
  a.map_offset = offset;
  a.map_size = length;
  *data = a.shadow;
  return VK_SUCCESS;
}

// Drops the shadow without a flush: unflushed writes are lost, as they may be on hardware.
VKAPI_ATTR void VKAPI_CALL unmap_memory(VkDevice device, VkDeviceMemory memory) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  if (const auto it = d.allocations.find(memory); it != d.allocations.end()) {
    Allocation& a = it->second;
    a.shadow_block.reset();
    a.shadow = a.real = nullptr;
    a.map_offset = a.map_size = 0;
  }
  d.next.unmap_memory(device, memory);
}

VKAPI_ATTR VkResult VKAPI_CALL flush_mapped_memory_ranges(VkDevice device, std::uint32_t count,
                                                          const VkMappedMemoryRange* ranges) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  std::vector<Span> spans;
  if (!check_ranges(d, count, ranges, "vkFlushMappedMemoryRanges", spans)) return VK_ERROR_UNKNOWN;
  for (const Span& s : spans) {
    const VkDeviceSize at = s.begin - s.allocation->map_offset;
    std::memcpy(s.allocation->real + at, s.allocation->shadow + at, s.end - s.begin);
    d.counters.bytes_flushed += s.end - s.begin;
  }
  return any_real_non_coherent(spans) ? d.next.flush_ranges(device, count, ranges) : VK_SUCCESS;
}

VKAPI_ATTR VkResult VKAPI_CALL invalidate_mapped_memory_ranges(VkDevice device, std::uint32_t count,
                                                               const VkMappedMemoryRange* ranges) {
  std::lock_guard lock(registry().mutex);
  DeviceState& d = device_state(device);
  std::vector<Span> spans;
  if (!check_ranges(d, count, ranges, "vkInvalidateMappedMemoryRanges", spans)) return VK_ERROR_UNKNOWN;
  if (any_real_non_coherent(spans))
    if (const VkResult r = d.next.invalidate_ranges(device, count, ranges); r != VK_SUCCESS) return r;
  for (const Span& s : spans) {
    const VkDeviceSize at = s.begin - s.allocation->map_offset;
    std::memcpy(s.allocation->shadow + at, s.allocation->real + at, s.end - s.begin);
    d.counters.bytes_invalidated += s.end - s.begin;
  }
  return VK_SUCCESS;
}

}  // namespace pond::layer
