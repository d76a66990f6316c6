#pragma once
// Saving a swapchain frame as PNG. The frame loop leaves the image in eTransferSrcOptimal and
// signals `drawn`; this copies it to a host buffer, hands the image on to presentation
// (ePresentSrcKHR, signalling the present semaphore) and writes the PNG atomically (core/png.h).
// Rare (F12, script, --screenshot): it waits for its copy, and the readback buffer is kept for the
// next shot of the same size.
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/context.h"

namespace pond::app::demo {

class ScreenshotWriter {
 public:
  explicit ScreenshotWriter(const gpu::Context& ctx);

  // Semaphore the frame loop signals for a screenshot frame (FrameTarget::signal_semaphore).
  vk::Semaphore drawn() const { return *drawn_; }
  // Copies `image` (format B8G8R8A8 or R8G8B8A8, in eTransferSrcOptimal after `drawn`), moves it to
  // ePresentSrcKHR signalling `present_ready`, and writes the picture to each of `paths`.
  void save(vk::Image image, vk::Format format, vk::Extent2D extent, vk::Semaphore present_ready,
            const std::vector<std::string>& paths);

 private:
  const gpu::Context& ctx_;
  vk::raii::Semaphore drawn_ = nullptr;
  vk::raii::CommandPool pool_ = nullptr;
  vk::raii::CommandBuffer cmd_ = nullptr;
  vk::raii::Fence fence_ = nullptr;
  gpu::Buffer readback_;
};

}  // namespace pond::app::demo
