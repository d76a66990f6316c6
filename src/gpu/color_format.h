#pragma once
// Which colour formats store sRGB: the hardware encodes on write, so the shaders output linear
// colour; a UNORM target (a swapchain fallback) needs the shaders to encode it themselves.
#include "gpu/vulkan.h"

namespace pond::gpu {

inline bool is_srgb(vk::Format f) {
  return f == vk::Format::eR8G8B8A8Srgb || f == vk::Format::eB8G8R8A8Srgb || f == vk::Format::eA8B8G8R8SrgbPack32;
}

}  // namespace pond::gpu
