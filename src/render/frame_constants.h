#pragma once
// What every part of a frame agrees on: how many frames may be in flight (each with its own
// resources, render/frame_data.h) and the depth format of the frame's and the reflection's passes.
#include <cstdint>

#include "gpu/vulkan.h"

namespace pond::render {

inline constexpr std::uint32_t kFramesInFlight = 2;
inline constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;

}  // namespace pond::render
