#pragma once
// The SPIR-V of pond's compute shaders, compiled at build time (cmake/Shaders.cmake), validated
// with spirv-val and embedded here.
#include <cstdint>
#include <span>

namespace pond::gpu {

std::span<const std::uint32_t> water_step_spirv();
std::span<const std::uint32_t> water_step_int64_spirv();  // 64-bit stores: needs shaderInt64
std::span<const std::uint32_t> water_perturb_spirv();
std::span<const std::uint32_t> water_normals_spirv();

}  // namespace pond::gpu
