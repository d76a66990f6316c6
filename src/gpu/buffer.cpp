#include "gpu/buffer.h"

#include <bit>
#include <cstring>

#include <vulkan/vulkan_format_traits.hpp>

#include "core/errors.h"

namespace pond::gpu {
namespace {
using MP = vk::MemoryPropertyFlagBits;
}  // namespace

std::uint32_t choose_memory_type(const vk::PhysicalDeviceMemoryProperties& props, std::uint32_t type_bits,
                                 vk::MemoryPropertyFlags required, vk::MemoryPropertyFlags preferred) {
  int best = -1, best_score = -1;
  for (std::uint32_t t = 0; t < props.memoryTypeCount; ++t) {
    const vk::MemoryPropertyFlags flags = props.memoryTypes[t].propertyFlags;
    if (!(type_bits & (1u << t)) || (flags & required) != required) continue;
    const int wanted = std::popcount(static_cast<std::uint32_t>(flags & preferred));
    const int extra = std::popcount(static_cast<std::uint32_t>(flags & ~(required | preferred)));
    const int score = wanted * 64 + (32 - extra);
    if (score > best_score) best = static_cast<int>(t), best_score = score;
  }
  if (best < 0) throw RuntimeError("no Vulkan memory type with the required properties " + vk::to_string(required));
  return static_cast<std::uint32_t>(best);
}

Buffer create_buffer(const Context& ctx, vk::DeviceSize size, vk::BufferUsageFlags usage, MemoryUse use,
                     const std::string& name) {
  Buffer b;
  b.size = size;
  b.buffer = vk::raii::Buffer(ctx.device(), vk::BufferCreateInfo{.size = size, .usage = usage,
                                                                 .sharingMode = vk::SharingMode::eExclusive});
  const vk::MemoryRequirements req = b.buffer.getMemoryRequirements();
  vk::MemoryPropertyFlags required, preferred;
  switch (use) {
    case MemoryUse::device: required = MP::eDeviceLocal; break;
    case MemoryUse::upload:
      required = MP::eHostVisible;
      preferred = MP::eHostCoherent;
      break;
    case MemoryUse::readback:
      required = MP::eHostVisible;
      preferred = MP::eHostCached | MP::eHostCoherent;
      break;
  }
  const vk::PhysicalDeviceMemoryProperties props = ctx.physical().getMemoryProperties();
  const std::uint32_t type = choose_memory_type(props, req.memoryTypeBits, required, preferred);
  b.memory = vk::raii::DeviceMemory(ctx.device(), vk::MemoryAllocateInfo{.allocationSize = req.size,
                                                                         .memoryTypeIndex = type});
  b.memory_size = req.size;
  b.buffer.bindMemory(*b.memory, 0);
  if (use != MemoryUse::device) {
    b.mapped = b.memory.mapMemory(0, VK_WHOLE_SIZE);
    b.coherent = static_cast<bool>(props.memoryTypes[type].propertyFlags & MP::eHostCoherent);
  }
  ctx.name(b.buffer, name);
  ctx.name(b.memory, name + " memory");
  return b;
}

void Buffer::invalidate(const Context& ctx) const {
  if (coherent || !mapped) return;
  ctx.device().invalidateMappedMemoryRanges(
      vk::MappedMemoryRange{.memory = *memory, .offset = 0, .size = VK_WHOLE_SIZE});
}

namespace {

// `bytes` from `offset` of b's mapping, rounded out to whole atoms, or up to the end of the mapping
// where the rounded range would pass it.
vk::MappedMemoryRange atom_range(const Context& ctx, const Buffer& b, vk::DeviceSize offset, vk::DeviceSize bytes) {
  const vk::DeviceSize atom = ctx.non_coherent_atom();
  const vk::DeviceSize begin = offset / atom * atom;
  const vk::DeviceSize end = bytes == VK_WHOLE_SIZE ? VK_WHOLE_SIZE : (offset + bytes + atom - 1) / atom * atom;
  return {.memory = *b.memory, .offset = begin, .size = end >= b.memory_size ? VK_WHOLE_SIZE : end - begin};
}

}  // namespace

void Buffer::invalidate_first(const Context& ctx, vk::DeviceSize bytes) const {
  if (coherent || !mapped || bytes == 0) return;
  ctx.device().invalidateMappedMemoryRanges(atom_range(ctx, *this, 0, bytes));
}

void Buffer::flush_range(const Context& ctx, vk::DeviceSize offset, vk::DeviceSize bytes) const {
  if (coherent || !mapped || bytes == 0) return;
  ctx.device().flushMappedMemoryRanges(atom_range(ctx, *this, offset, bytes));
}

void upload(const Context& ctx, const Buffer& dst, std::span<const std::byte> bytes) {
  if (bytes.empty()) return;
  const Buffer staging = create_buffer(ctx, bytes.size(), vk::BufferUsageFlagBits::eTransferSrc,
                                       MemoryUse::upload, "upload staging");
  std::memcpy(staging.mapped, bytes.data(), bytes.size());
  staging.flush(ctx);
  ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    cmd.copyBuffer(*staging.buffer, *dst.buffer, vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = bytes.size()});
  });
}

vk::raii::BufferView create_texel_view(const Context& ctx, const Buffer& buffer, vk::Format format, const char* what) {
  const vk::DeviceSize texels = buffer.size / vk::blockSize(format);
  const std::uint32_t limit = ctx.physical().getProperties().limits.maxTexelBufferElements;
  if (texels > limit)
    throw RuntimeError(std::string(what) + " needs a texel buffer of " + std::to_string(texels) +
                       " elements; this device's maxTexelBufferElements is " + std::to_string(limit) +
                       " (a smaller grid or a CPU solver runs)");
  return vk::raii::BufferView(ctx.device(), vk::BufferViewCreateInfo{.buffer = *buffer.buffer, .format = format,
                                                                     .offset = 0, .range = VK_WHOLE_SIZE});
}

bool host_readable_in_place(const Context& ctx, const Buffer& b) {
  const vk::MemoryPropertyFlags host = MP::eHostVisible | MP::eHostCached | MP::eHostCoherent;
  const vk::PhysicalDeviceMemoryProperties props = ctx.physical().getMemoryProperties();
  const std::uint32_t bits = b.buffer.getMemoryRequirements().memoryTypeBits;
  for (std::uint32_t t = 0; t < props.memoryTypeCount; ++t) {
    const vk::MemoryPropertyFlags flags = props.memoryTypes[t].propertyFlags;
    if ((bits >> t & 1u) && (flags & MP::eDeviceLocal) && (flags & host) != host) return false;
  }
  return true;
}

}  // namespace pond::gpu
