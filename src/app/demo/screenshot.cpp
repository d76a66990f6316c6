#include "app/demo/screenshot.h"

#include <cstring>
#include <vector>

#include "core/errors.h"
#include "core/png.h"

namespace pond::app::demo {

ScreenshotWriter::ScreenshotWriter(const gpu::Context& ctx) : ctx_(ctx) {
  drawn_ = vk::raii::Semaphore(ctx.device(), vk::SemaphoreCreateInfo{});
  ctx.name(drawn_, "demo screenshot drawn");
  pool_ = vk::raii::CommandPool(ctx.device(), vk::CommandPoolCreateInfo{
                                                  .flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                  .queueFamilyIndex = ctx.queue_family()});
  vk::raii::CommandBuffers buffers(ctx.device(), vk::CommandBufferAllocateInfo{
                                                     .commandPool = *pool_, .level = vk::CommandBufferLevel::ePrimary,
                                                     .commandBufferCount = 1});
  cmd_ = std::move(buffers[0]);
  fence_ = vk::raii::Fence(ctx.device(), vk::FenceCreateInfo{});
}

void ScreenshotWriter::save(vk::Image image, vk::Format format, vk::Extent2D extent, vk::Semaphore present_ready,
                            const std::vector<std::string>& paths) {
  const bool bgra = format == vk::Format::eB8G8R8A8Srgb || format == vk::Format::eB8G8R8A8Unorm;
  if (!bgra && format != vk::Format::eR8G8B8A8Srgb && format != vk::Format::eR8G8B8A8Unorm)
    throw RuntimeError("screenshots of swapchain format " + vk::to_string(format) + " are not supported");
  const vk::DeviceSize bytes = vk::DeviceSize(extent.width) * extent.height * 4;
  if (readback_.size < bytes)
    readback_ = gpu::create_buffer(ctx_, bytes, vk::BufferUsageFlagBits::eTransferDst, gpu::MemoryUse::readback,
                                   "demo screenshot readback");

  cmd_.reset();
  cmd_.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  const vk::BufferImageCopy copy{.imageSubresource = {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                 .imageExtent = {extent.width, extent.height, 1}};
  cmd_.copyImageToBuffer(image, vk::ImageLayout::eTransferSrcOptimal, *readback_.buffer, copy);
  const vk::ImageMemoryBarrier2 to_present{.srcStageMask = vk::PipelineStageFlagBits2::eCopy,
                                           .srcAccessMask = vk::AccessFlagBits2::eNone,
                                           .dstStageMask = vk::PipelineStageFlagBits2::eNone,
                                           .dstAccessMask = vk::AccessFlagBits2::eNone,
                                           .oldLayout = vk::ImageLayout::eTransferSrcOptimal,
                                           .newLayout = vk::ImageLayout::ePresentSrcKHR,
                                           .image = image,
                                           .subresourceRange = {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}};
  const vk::BufferMemoryBarrier2 to_host{.srcStageMask = vk::PipelineStageFlagBits2::eCopy,
                                         .srcAccessMask = vk::AccessFlagBits2::eTransferWrite,
                                         .dstStageMask = vk::PipelineStageFlagBits2::eHost,
                                         .dstAccessMask = vk::AccessFlagBits2::eHostRead,
                                         .buffer = *readback_.buffer, .offset = 0, .size = VK_WHOLE_SIZE};
  cmd_.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &to_host,
                                           .imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &to_present});
  cmd_.end();
  const vk::SemaphoreSubmitInfo wait{.semaphore = *drawn_, .stageMask = vk::PipelineStageFlagBits2::eCopy};
  const vk::SemaphoreSubmitInfo signal{.semaphore = present_ready, .stageMask = vk::PipelineStageFlagBits2::eAllCommands};
  const vk::CommandBufferSubmitInfo cmd_info{.commandBuffer = *cmd_};
  ctx_.queue().submit2(vk::SubmitInfo2{.waitSemaphoreInfoCount = 1, .pWaitSemaphoreInfos = &wait,
                                       .commandBufferInfoCount = 1, .pCommandBufferInfos = &cmd_info,
                                       .signalSemaphoreInfoCount = 1, .pSignalSemaphoreInfos = &signal},
                       *fence_);
  if (ctx_.device().waitForFences(*fence_, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
    throw RuntimeError("waiting for the screenshot copy failed");
  ctx_.device().resetFences(*fence_);
  readback_.invalidate(ctx_);

  std::vector<std::uint8_t> rgba(bytes);
  std::memcpy(rgba.data(), readback_.mapped, bytes);
  if (bgra)
    for (std::size_t p = 0; p < rgba.size(); p += 4) std::swap(rgba[p], rgba[p + 2]);
  for (std::size_t p = 3; p < rgba.size(); p += 4) rgba[p] = 255;  // the window is opaque
  for (const std::string& path : paths)
    pond::write_png(path, static_cast<int>(extent.width), static_cast<int>(extent.height), rgba);
}

}  // namespace pond::app::demo
