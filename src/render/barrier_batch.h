#pragma once
// Barriers gathered from several passes and recorded as one vkCmdPipelineBarrier2. Fewer, fuller
// barrier commands are good practice on any device, and on lavapipe they are what lets passes
// overlap: it finishes every queued draw and dispatch at each barrier command.
#include <vector>

#include "gpu/context.h"

namespace pond::render {

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
