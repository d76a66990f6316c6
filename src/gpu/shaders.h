#pragma once
// The SPIR-V of pond's compute shaders, compiled at build time (cmake/Shaders.cmake), validated
// with spirv-val and embedded here. Each comes with and without the DenormPreserve execution mode
// (for devices that advertise shaderDenormPreserveFloat32, gpu/float_policy.h); the step shader
// also with 64-bit stores (needs shaderInt64).
#include <cstdint>
#include <span>

namespace pond::gpu {

std::span<const std::uint32_t> water_step_spirv(bool int64_stores, bool denorm_preserve);
std::span<const std::uint32_t> water_perturb_spirv(bool denorm_preserve);
std::span<const std::uint32_t> water_normals_spirv(bool denorm_preserve);
// The normals that also write the tile bounds' columns, and the tiles from those (tile_kernels.h).
std::span<const std::uint32_t> water_normals_tiles_spirv(bool denorm_preserve);
std::span<const std::uint32_t> water_tiles_spirv(bool denorm_preserve);
std::span<const std::uint32_t> water_contact_spirv(bool denorm_preserve);
// Runs of the state packed for the host (displacement_readback.h): bit copies, one variant.
std::span<const std::uint32_t> water_gather_spirv();

}  // namespace pond::gpu
