#pragma once
// Buffers with an explicit memory-type choice. Three uses, three choices:
//  - device:   DEVICE_LOCAL required; the GPU's own memory (state, mask, tables, normals).
//  - upload:   HOST_VISIBLE required, HOST_COHERENT preferred; written by the CPU, read by the
//              GPU. Where it is not coherent, the writer flushes what it wrote (flush()).
//  - readback: HOST_VISIBLE required, HOST_CACHED preferred (the CPU reads it), HOST_COHERENT
//              preferred (otherwise the range is invalidated before reading: invalidate()).
// On lavapipe every type has every flag; a discrete GPU (or the test layer in layers/, which
// presents lavapipe as one) has neither a host-visible device-local type nor coherent ones.
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
  vk::DeviceSize memory_size = 0;  // of its allocation (at least `size`)
  void* mapped = nullptr;  // upload and readback buffers stay mapped
  bool coherent = true;

  vk::DescriptorBufferInfo whole() const { return {.buffer = *buffer, .offset = 0, .range = VK_WHOLE_SIZE}; }
  // Makes GPU writes visible to the host (no-op for coherent memory); call after the fence.
  void invalidate(const Context& ctx) const;
  // The same for the first `bytes` (rounded out to whole atoms).
  void invalidate_first(const Context& ctx, vk::DeviceSize bytes) const;
  // Makes the host's writes to the first `bytes` (whole atoms; default: all) visible to the GPU
  // (no-op for coherent memory); call before the submission that reads them.
  void flush(const Context& ctx, vk::DeviceSize bytes = VK_WHOLE_SIZE) const { flush_range(ctx, 0, bytes); }
  // The same for `bytes` from `offset` (rounded out to whole atoms).
  void flush_range(const Context& ctx, vk::DeviceSize offset, vk::DeviceSize bytes) const;
};

// The index of the memory type for `type_bits` with all `required` flags and as many `preferred`
// as possible (fewest extra flags on ties). Throws RuntimeError when none fits.
std::uint32_t choose_memory_type(const vk::PhysicalDeviceMemoryProperties& props, std::uint32_t type_bits,
                                 vk::MemoryPropertyFlags required, vk::MemoryPropertyFlags preferred);

Buffer create_buffer(const Context& ctx, vk::DeviceSize size, vk::BufferUsageFlags usage, MemoryUse use,
                     const std::string& name);

// A texel-buffer view of the whole of `buffer` as texels of `format`. Throws RuntimeError naming
// `what` when the view would hold more texels than the device's maxTexelBufferElements (at least
// 65536 on every device; a 257^2 grid's state needs more).
vk::raii::BufferView create_texel_view(const Context& ctx, const Buffer& buffer, vk::Format format, const char* what);

// Whether the host can read device buffer `b` in place: every device-local memory type it could be
// in is also host-visible, cached and coherent (lavapipe: the "GPU" memory is the CPU's).
bool host_readable_in_place(const Context& ctx, const Buffer& b);

// Fills a device buffer from host bytes through a temporary upload buffer (waits for the copy).
void upload(const Context& ctx, const Buffer& dst, std::span<const std::byte> bytes);

}  // namespace pond::gpu
