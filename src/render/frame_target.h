#pragma once
// The image a frame is drawn into: an offscreen RenderTarget (render_target.h) or a swapchain
// image. The main pass transitions it from `old_layout` (eUndefined: contents discarded, it is
// cleared) to the color-attachment layout and, at the end, to `final_layout` (ePresentSrcKHR for
// a swapchain, eTransferSrcOptimal for readback).
#include "gpu/vulkan.h"

namespace pond::render {

struct FrameTarget {
  vk::Image image;
  vk::ImageView view;
  vk::Format format = vk::Format::eUndefined;
  vk::Extent2D extent;
  vk::ImageLayout old_layout = vk::ImageLayout::eUndefined;
  vk::ImageLayout final_layout = vk::ImageLayout::eTransferSrcOptimal;
  vk::Semaphore wait_semaphore;    // optional: waited before color output (swapchain acquire)
  vk::Semaphore signal_semaphore;  // optional: signalled when the frame is drawn (present waits)
};

}  // namespace pond::render
