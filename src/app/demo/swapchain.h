#pragma once
// The window's swapchain (vk::raii): images, their views and one "rendered" semaphore per image
// (present waits on it; it is reused only when the same image comes back from acquire). Recreated
// on resize, after minimize, when the driver says it is out of date, and to switch vsync.
//
// Acquire semaphores: a ring of FrameLoop::kFramesInFlight + 1. Acquire number n signals
// acquired[n % ring]; the FrameLoop draw that waits on it is frame call n. Before acquire n + ring
// the loop has started frame call n + ring - 1, which waited for its slot's fence, i.e. for frame
// call n + ring - 1 - kFramesInFlight = n: so the semaphore's previous wait has completed, as
// vkAcquireNextImageKHR requires, without a fence or a waitIdle of our own.
#include <cstdint>
#include <optional>
#include <vector>

#include "gpu/context.h"

namespace pond::app::demo {

struct AcquiredImage {
  std::uint32_t index = 0;
  vk::Image image;
  vk::ImageView view;
  vk::Semaphore acquired;  // signalled when the image may be written
  vk::Semaphore rendered;  // to signal when drawing is done; present waits on it
  bool suboptimal = false;
};

class Swapchain {
 public:
  static constexpr std::uint32_t kAcquireRing = 3;  // FrameLoop::kFramesInFlight + 1 (checked in demo_app.cpp)

  Swapchain(const gpu::Context& ctx, vk::Extent2D extent, bool vsync);
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // The format is chosen once (pipelines are built for it) and kept across recreation.
  vk::Format format() const { return format_; }
  vk::Extent2D extent() const { return extent_; }
  bool vsync() const { return vsync_; }
  vk::PresentModeKHR present_mode() const { return present_mode_; }
  std::uint32_t image_count() const { return static_cast<std::uint32_t>(images_.size()); }
  bool can_copy_images() const { return transfer_src_; }  // screenshots read the image back

  // Waits for the device to be idle and rebuilds for `extent` (clamped to the surface's limits).
  void recreate(vk::Extent2D extent, bool vsync);
  // Next image, or nothing when the swapchain is out of date (recreate, then try again).
  std::optional<AcquiredImage> acquire();
  // Presents; false when the swapchain is out of date or suboptimal (recreate).
  bool present(const AcquiredImage& image);

 private:
  void build(vk::Extent2D extent);

  const gpu::Context& ctx_;
  vk::Format format_ = vk::Format::eUndefined;
  vk::ColorSpaceKHR color_space_ = vk::ColorSpaceKHR::eSrgbNonlinear;
  vk::Extent2D extent_;
  bool vsync_ = true;
  vk::PresentModeKHR present_mode_ = vk::PresentModeKHR::eFifo;
  bool transfer_src_ = false;
  vk::raii::SwapchainKHR swapchain_ = nullptr;
  std::vector<vk::Image> images_;
  std::vector<vk::raii::ImageView> views_;
  std::vector<vk::raii::Semaphore> rendered_;
  std::vector<vk::raii::Semaphore> acquired_;
  std::uint64_t acquires_ = 0;
};

}  // namespace pond::app::demo
