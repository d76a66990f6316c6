#pragma once
// Images the renderer draws into: the offscreen color target of `pond render` (drawn by the frame
// loop, then read back as RGBA8) and the depth images of the frame loop.
#include <cstdint>
#include <string>
#include <vector>

#include "render/color_format.h"
#include "gpu/context.h"
#include "render/frame_target.h"

namespace pond::render {

// A 2D image with its own device memory and a view of all of it.
struct Image {
  vk::raii::Image image = nullptr;
  vk::raii::DeviceMemory memory = nullptr;
  vk::raii::ImageView view = nullptr;
  vk::Format format = vk::Format::eUndefined;
  vk::Extent2D extent;
};

Image create_image(const gpu::Context& ctx, vk::Extent2D extent, vk::Format format, vk::ImageUsageFlags usage,
                   vk::ImageAspectFlags aspect, const std::string& name);

// Throws InputError when a width x height color target with `format` is beyond what the device
// can render or hold (checked before any work, so `pond render` refuses bad sizes up front).
void check_target_size(const gpu::Context& ctx, int width, int height, vk::Format format);

// The offscreen color image of headless rendering, RGBA8 holding sRGB-encoded colour: UNORM, the
// shaders encoding (kFormat, render/color_format.h), or R8G8B8A8Srgb, the format encoding.
class RenderTarget {
 public:
  static constexpr vk::Format kFormat = kColorFormat;

  RenderTarget(const gpu::Context& ctx, int width, int height, vk::Format format = kFormat);

  // The FrameTarget for a frame (render/frame_loop.h): cleared each frame, left in eTransferSrcOptimal.
  FrameTarget frame_target() const;
  // The last drawn frame as RGBA8 rows, top row first. The frame must have been submitted; this
  // waits for it (the copy is queued behind it).
  std::vector<std::uint8_t> read_rgba();  // not const: it waits

  int width() const { return static_cast<int>(image_.extent.width); }
  int height() const { return static_cast<int>(image_.extent.height); }

 private:
  const gpu::Context& ctx_;
  Image image_;
};

}  // namespace pond::render
