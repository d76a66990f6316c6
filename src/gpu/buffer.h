#pragma once
// Buffers with an explicit memory-type choice. Three uses, three choices:
//  - device:   DEVICE_LOCAL required; the GPU's own memory (state, mask, tables, normals).
//  - upload:   HOST_VISIBLE | HOST_COHERENT required; written by the CPU, copied from by the GPU.
//  - readback: HOST_VISIBLE required, HOST_CACHED preferred (the CPU reads it), HOST_COHERENT
//              preferred (otherwise the range is invalidated before reading).
// On lavapipe every type has every flag, so the choice only matters on real GPUs; it is still made
// the same way everywhere.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "gpu/context.h"

namespace pond::gpu {

enum class MemoryUse { device, upload, readback };

struct Buffer {
  vk::raii::Buffer buffer = nullptr;
  vk::raii::DeviceMemory memory = nullptr;
  vk::DeviceSize size = 0;
  void* mapped = nullptr;  // upload and readback buffers stay mapped
  bool coherent = true;

  vk::DescriptorBufferInfo whole() const { return {.buffer = *buffer, .offset = 0, .range = VK_WHOLE_SIZE}; }
  // Makes GPU writes visible to the host (no-op for coherent memory); call after the fence.
  void invalidate(const Context& ctx) const;
};

// The index of the memory type for `type_bits` with all `required` flags and as many `preferred`
// as possible (fewest extra flags on ties). Throws RuntimeError when none fits.
std::uint32_t choose_memory_type(const vk::PhysicalDeviceMemoryProperties& props, std::uint32_t type_bits,
                                 vk::MemoryPropertyFlags required, vk::MemoryPropertyFlags preferred);

Buffer create_buffer(const Context& ctx, vk::DeviceSize size, vk::BufferUsageFlags usage, MemoryUse use,
                     const std::string& name);

// Fills a device buffer from host bytes through a temporary upload buffer (waits for the copy).
void upload(const Context& ctx, const Buffer& dst, std::span<const std::byte> bytes);

}  // namespace pond::gpu
