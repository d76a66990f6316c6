#pragma once
// The one include of Vulkan-Hpp for pond. Everything goes through vk::raii, whose dispatchers are
// loaded at run time from libvulkan.so.1: `pond` does not link the loader, so the CPU commands run
// on a machine without Vulkan and the GPU path can report "no Vulkan" instead of failing to start.
#define VULKAN_HPP_NO_CONSTRUCTORS  // designated initializers for create-info structs
#include <vulkan/vulkan_raii.hpp>
