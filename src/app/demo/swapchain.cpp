#include "app/demo/swapchain.h"

#include <algorithm>

#include "core/errors.h"
#include "render/color_format.h"

namespace pond::app::demo {
namespace {

// The renderer draws into UNORM images, its shaders encoding sRGB (render/color_format.h: much cheaper
// than the format's encoding on llvmpipe), as into its offscreen target; an sRGB format is the
// fallback, where the shaders output linear colour. (The ImGui shader linearizes its sRGB-authored
// colours for sRGB targets.)
vk::SurfaceFormatKHR choose_format(const std::vector<vk::SurfaceFormatKHR>& formats) {
  for (vk::Format want : {vk::Format::eB8G8R8A8Unorm, render::kColorFormat, vk::Format::eB8G8R8A8Srgb,
                          vk::Format::eR8G8B8A8Srgb})
    for (const auto& f : formats)
      if (f.format == want && f.colorSpace == vk::ColorSpaceKHR::eSrgbNonlinear) return f;
  if (formats.empty()) throw RuntimeError("the window's surface offers no image format");
  return formats.front();
}

// Without vsync: mailbox (no tearing) or immediate; with vsync FIFO, which every driver has.
vk::PresentModeKHR choose_present_mode(const std::vector<vk::PresentModeKHR>& modes, bool vsync) {
  if (vsync) return vk::PresentModeKHR::eFifo;
  for (vk::PresentModeKHR want : {vk::PresentModeKHR::eImmediate, vk::PresentModeKHR::eMailbox})
    if (std::find(modes.begin(), modes.end(), want) != modes.end()) return want;
  return vk::PresentModeKHR::eFifo;
}

}  // namespace

Swapchain::Swapchain(const gpu::Context& ctx, vk::Extent2D extent, bool vsync) : ctx_(ctx), vsync_(vsync) {
  if (!*ctx.surface()) throw RuntimeError("internal: the Vulkan context has no window surface");
  const auto formats = ctx.physical().getSurfaceFormatsKHR(*ctx.surface());
  const vk::SurfaceFormatKHR chosen = choose_format(formats);
  format_ = chosen.format;
  color_space_ = chosen.colorSpace;
  for (std::uint32_t k = 0; k < kAcquireRing; ++k) {
    acquired_.emplace_back(ctx.device(), vk::SemaphoreCreateInfo{});
    ctx.name(acquired_.back(), "demo acquire semaphore " + std::to_string(k));
  }
  build(extent);
}

void Swapchain::recreate(vk::Extent2D extent, bool vsync) {
  ctx_.device().waitIdle();  // the old images may still be drawn or presented
  vsync_ = vsync;
  build(extent);
}

void Swapchain::build(vk::Extent2D extent) {
  const vk::raii::PhysicalDevice& physical = ctx_.physical();
  const vk::SurfaceKHR surface = *ctx_.surface();
  const vk::SurfaceCapabilitiesKHR caps = physical.getSurfaceCapabilitiesKHR(surface);
  if (caps.currentExtent.width != 0xFFFFFFFFu) extent = caps.currentExtent;
  extent.width = std::clamp(extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
  extent.height = std::clamp(extent.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  present_mode_ = choose_present_mode(physical.getSurfacePresentModesKHR(surface), vsync_);
  std::uint32_t count = std::max(caps.minImageCount + 1, 3u);
  if (caps.maxImageCount != 0) count = std::min(count, caps.maxImageCount);
  transfer_src_ = static_cast<bool>(caps.supportedUsageFlags & vk::ImageUsageFlagBits::eTransferSrc);
  vk::ImageUsageFlags usage = vk::ImageUsageFlagBits::eColorAttachment;
  if (transfer_src_) usage |= vk::ImageUsageFlagBits::eTransferSrc;

  vk::raii::SwapchainKHR old = std::move(swapchain_);
  swapchain_ = vk::raii::SwapchainKHR(
      ctx_.device(), vk::SwapchainCreateInfoKHR{.surface = surface,
                                                .minImageCount = count,
                                                .imageFormat = format_,
                                                .imageColorSpace = color_space_,
                                                .imageExtent = extent,
                                                .imageArrayLayers = 1,
                                                .imageUsage = usage,
                                                .imageSharingMode = vk::SharingMode::eExclusive,
                                                .preTransform = caps.currentTransform,
                                                .compositeAlpha = vk::CompositeAlphaFlagBitsKHR::eOpaque,
                                                .presentMode = present_mode_,
                                                .clipped = VK_TRUE,
                                                .oldSwapchain = *old});
  extent_ = extent;
  views_.clear();
  rendered_.clear();
  images_ = swapchain_.getImages();
  for (std::size_t k = 0; k < images_.size(); ++k) {
    views_.emplace_back(ctx_.device(), vk::ImageViewCreateInfo{
                                           .image = images_[k],
                                           .viewType = vk::ImageViewType::e2D,
                                           .format = format_,
                                           .subresourceRange = {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}});
    rendered_.emplace_back(ctx_.device(), vk::SemaphoreCreateInfo{});
    ctx_.name(rendered_.back(), "demo rendered semaphore " + std::to_string(k));
  }
}

std::optional<AcquiredImage> Swapchain::acquire() {
  const vk::Semaphore sem = *acquired_[acquires_ % kAcquireRing];
  // vk::raii throws on eErrorOutOfDateKHR; the C entry point reports it as a value.
  std::uint32_t index = 0;
  const VkResult r = ctx_.device().getDispatcher()->vkAcquireNextImageKHR(
      static_cast<VkDevice>(*ctx_.device()), static_cast<VkSwapchainKHR>(*swapchain_), UINT64_MAX,
      static_cast<VkSemaphore>(sem), VK_NULL_HANDLE, &index);
  if (r == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt;
  if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR)  // Vulkan-Hpp's exception: a lost device is told apart
    vk::resultCheck(static_cast<vk::Result>(r), "vkAcquireNextImageKHR");
  ++acquires_;
  return AcquiredImage{.index = index, .image = images_[index], .view = *views_[index], .acquired = sem,
                       .rendered = *rendered_[index], .suboptimal = r == VK_SUBOPTIMAL_KHR};
}

bool Swapchain::present(const AcquiredImage& image) {
  const VkSemaphore wait = static_cast<VkSemaphore>(image.rendered);
  const VkSwapchainKHR chain = static_cast<VkSwapchainKHR>(*swapchain_);
  const VkPresentInfoKHR info{.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR, .pNext = nullptr, .waitSemaphoreCount = 1,
                              .pWaitSemaphores = &wait, .swapchainCount = 1, .pSwapchains = &chain,
                              .pImageIndices = &image.index, .pResults = nullptr};
  const VkResult r = ctx_.queue().getDispatcher()->vkQueuePresentKHR(static_cast<VkQueue>(*ctx_.queue()), &info);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) return false;
  if (r != VK_SUCCESS) vk::resultCheck(static_cast<vk::Result>(r), "vkQueuePresentKHR");
  return !image.suboptimal;
}

}  // namespace pond::app::demo
