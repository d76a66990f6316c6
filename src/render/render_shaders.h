#pragma once
// The SPIR-V of the water renderer's shaders (shaders/water.*, land.*, sky.*,
// caustics.comp), compiled at build time,
// validated with spirv-val and embedded (cmake/Shaders.cmake).
#include <cstdint>
#include <span>

namespace pond::render {

std::span<const std::uint32_t> water_vert_spirv();
std::span<const std::uint32_t> water_frag_spirv();
std::span<const std::uint32_t> water_wire_frag_spirv();
std::span<const std::uint32_t> land_vert_spirv();
std::span<const std::uint32_t> land_frag_spirv();
std::span<const std::uint32_t> water_reflect_frag_spirv();
std::span<const std::uint32_t> land_mirror_vert_spirv();
std::span<const std::uint32_t> land_submerged_vert_spirv();  // front faces only
std::span<const std::uint32_t> land_submerged_frag_spirv();
std::span<const std::uint32_t> land_mirror_frag_spirv();  // without the shadow map
std::span<const std::uint32_t> sky_vert_spirv();
std::span<const std::uint32_t> sky_frag_spirv();
std::span<const std::uint32_t> caustics_comp_spirv();

}  // namespace pond::render
