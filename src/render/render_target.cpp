#include "render/render_target.h"

#include <cstring>

#include "core/errors.h"
#include "gpu/buffer.h"

namespace pond::render {
namespace {
using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
}  // namespace

Image create_image(const gpu::Context& ctx, vk::Extent2D extent, vk::Format format, vk::ImageUsageFlags usage,
                   vk::ImageAspectFlags aspect, const std::string& name) {
  Image img;
  img.format = format;
  img.extent = extent;
  img.image = vk::raii::Image(ctx.device(), vk::ImageCreateInfo{.imageType = vk::ImageType::e2D,
                                                                .format = format,
                                                                .extent = {extent.width, extent.height, 1},
                                                                .mipLevels = 1,
                                                                .arrayLayers = 1,
                                                                .samples = vk::SampleCountFlagBits::e1,
                                                                .tiling = vk::ImageTiling::eOptimal,
                                                                .usage = usage,
                                                                .sharingMode = vk::SharingMode::eExclusive,
                                                                .initialLayout = vk::ImageLayout::eUndefined});
  const vk::MemoryRequirements req = img.image.getMemoryRequirements();
  const std::uint32_t type = gpu::choose_memory_type(ctx.physical().getMemoryProperties(), req.memoryTypeBits,
                                                vk::MemoryPropertyFlagBits::eDeviceLocal, {});
  img.memory = vk::raii::DeviceMemory(ctx.device(), vk::MemoryAllocateInfo{.allocationSize = req.size,
                                                                           .memoryTypeIndex = type});
  img.image.bindMemory(*img.memory, 0);
  img.view = vk::raii::ImageView(
      ctx.device(), vk::ImageViewCreateInfo{.image = *img.image, .viewType = vk::ImageViewType::e2D, .format = format,
                                            .subresourceRange = {.aspectMask = aspect, .baseMipLevel = 0, .levelCount = 1,
                                                                 .baseArrayLayer = 0, .layerCount = 1}});
  ctx.name(img.image, name);
  ctx.name(img.view, name + " view");
  return img;
}

void check_target_size(const gpu::Context& ctx, int width, int height, vk::Format format) {
  const vk::PhysicalDeviceLimits limits = ctx.physical().getProperties().limits;
  const auto max_w = std::min({limits.maxImageDimension2D, limits.maxFramebufferWidth, limits.maxViewportDimensions[0]});
  const auto max_h = std::min({limits.maxImageDimension2D, limits.maxFramebufferHeight, limits.maxViewportDimensions[1]});
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width < 1 || height < 1) throw InputError("--size " + size + ": width and height must be at least 1");
  if (static_cast<std::uint32_t>(width) > max_w || static_cast<std::uint32_t>(height) > max_h)
    throw InputError("--size " + size + " is beyond the device's limits (at most " + std::to_string(max_w) + "x" +
                     std::to_string(max_h) + " on " + ctx.device_name() + ")");
  const vk::ImageFormatProperties props = ctx.physical().getImageFormatProperties(
      format, vk::ImageType::e2D, vk::ImageTiling::eOptimal,
      vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc);
  // Color + two depth images + the readback buffer, against the largest heap.
  const double bytes = 4.0 * width * height * 4;
  double heap = 0;
  const auto mem = ctx.physical().getMemoryProperties();
  for (std::uint32_t h = 0; h < mem.memoryHeapCount; ++h) heap = std::max(heap, static_cast<double>(mem.memoryHeaps[h].size));
  if (bytes > std::min(static_cast<double>(props.maxResourceSize), heap / 2))
    throw InputError("--size " + size + " needs " + std::to_string(static_cast<long long>(bytes / (1 << 20))) +
                     " MiB of images, more than " + ctx.device_name() + " allows");
}

RenderTarget::RenderTarget(const gpu::Context& ctx, int width, int height, vk::Format format)
    : ctx_(ctx),
      image_(create_image(ctx, vk::Extent2D{static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)},
                          format, vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc,
                          vk::ImageAspectFlagBits::eColor, "offscreen color target")) {}

FrameTarget RenderTarget::frame_target() const {
  return FrameTarget{.image = *image_.image, .view = *image_.view, .format = image_.format, .extent = image_.extent,
                     .old_layout = vk::ImageLayout::eUndefined,
                     .final_layout = vk::ImageLayout::eTransferSrcOptimal, .wait_semaphore = {}, .signal_semaphore = {}};
}

std::vector<std::uint8_t> RenderTarget::read_rgba() {
  const std::size_t bytes = std::size_t{image_.extent.width} * image_.extent.height * 4;
  const gpu::Buffer staging = gpu::create_buffer(ctx_, bytes, vk::BufferUsageFlagBits::eTransferDst, gpu::MemoryUse::readback,
                                       "color readback");
  ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    // The frame's color writes (its final layout transition included) before the copy reads them.
    const vk::MemoryBarrier2 after_draw{.srcStageMask = S::eColorAttachmentOutput | S::eAllCommands,
                                        .srcAccessMask = A::eColorAttachmentWrite,
                                        .dstStageMask = S::eCopy, .dstAccessMask = A::eTransferRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &after_draw});
    const vk::BufferImageCopy region{
        .bufferOffset = 0, .bufferRowLength = 0, .bufferImageHeight = 0,
        .imageSubresource = {.aspectMask = vk::ImageAspectFlagBits::eColor, .mipLevel = 0, .baseArrayLayer = 0, .layerCount = 1},
        .imageOffset = {0, 0, 0}, .imageExtent = {image_.extent.width, image_.extent.height, 1}};
    cmd.copyImageToBuffer(*image_.image, vk::ImageLayout::eTransferSrcOptimal, *staging.buffer, region);
    const vk::MemoryBarrier2 to_host{.srcStageMask = S::eCopy, .srcAccessMask = A::eTransferWrite,
                                     .dstStageMask = S::eHost, .dstAccessMask = A::eHostRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
  });
  staging.invalidate(ctx_);
  std::vector<std::uint8_t> rgba(bytes);
  std::memcpy(rgba.data(), staging.mapped, bytes);
  return rgba;
}

}  // namespace pond::render
