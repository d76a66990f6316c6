#pragma once
// Barriers gathered from several passes and recorded as one vkCmdPipelineBarrier2. Fewer, fuller
// barrier commands are good practice on any device, and on lavapipe they are what lets passes
// overlap: it finishes every queued draw and dispatch at each barrier command.
#include <vector>

#include "gpu/context.h"

namespace pond::render {

// The one image barrier every pass and target builds: the whole image (one mip, one layer) of
// `aspect` from layout `from` to `to`, queue families ignored.
inline vk::ImageMemoryBarrier2 image_barrier(vk::Image image, vk::ImageAspectFlags aspect, vk::ImageLayout from,
                                             vk::ImageLayout to, vk::PipelineStageFlags2 src_stage,
                                             vk::AccessFlags2 src_access, vk::PipelineStageFlags2 dst_stage,
                                             vk::AccessFlags2 dst_access) {
  return {.srcStageMask = src_stage, .srcAccessMask = src_access, .dstStageMask = dst_stage, .dstAccessMask = dst_access,
          .oldLayout = from, .newLayout = to, .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
          .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .image = image,
          .subresourceRange = {.aspectMask = aspect, .baseMipLevel = 0, .levelCount = 1, .baseArrayLayer = 0, .layerCount = 1}};
}

struct BarrierBatch {
  std::vector<vk::MemoryBarrier2> memory;
  std::vector<vk::ImageMemoryBarrier2> images;

  // Records what was gathered, if anything, and empties the batch.
  void record(const vk::raii::CommandBuffer& cmd) {
    if (memory.empty() && images.empty()) return;
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = static_cast<std::uint32_t>(memory.size()),
                                            .pMemoryBarriers = memory.data(),
                                            .imageMemoryBarrierCount = static_cast<std::uint32_t>(images.size()),
                                            .pImageMemoryBarriers = images.data()});
    memory.clear();
    images.clear();
  }
};

}  // namespace pond::render
