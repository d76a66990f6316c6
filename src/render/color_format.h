#pragma once
// Colour formats. pond draws into UNORM images and its shaders encode sRGB themselves (a
// specialization constant, shared/water_shading.h): on llvmpipe an sRGB format's encoding on
// every store costs far more than the shaders' polynomial (docs/perf.md); on a GPU either is
// free. An sRGB target still works (a surface that offers nothing else): the hardware encodes,
// the shaders output linear colour.
#include "gpu/vulkan.h"

namespace pond::render {

// The offscreen target's format (RenderTarget::kFormat), and the swapchain's first choice after its
// BGRA twin (app/demo/swapchain.cpp).
inline constexpr vk::Format kColorFormat = vk::Format::eR8G8B8A8Unorm;

inline bool is_srgb(vk::Format f) {
  return f == vk::Format::eR8G8B8A8Srgb || f == vk::Format::eB8G8R8A8Srgb || f == vk::Format::eA8B8G8R8SrgbPack32;
}

}  // namespace pond::render
