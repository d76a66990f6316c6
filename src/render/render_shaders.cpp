#include "render/render_shaders.h"

namespace pond::render {
namespace {
#include "caustics_comp.spv.h"
#include "land_frag.spv.h"
#include "land_mirror_frag.spv.h"
#include "land_mirror_vert.spv.h"
#include "land_submerged_frag.spv.h"
#include "land_submerged_vert.spv.h"
#include "land_vert.spv.h"
#include "water_reflect_frag.spv.h"
#include "sky_frag.spv.h"
#include "sky_vert.spv.h"
#include "water_frag.spv.h"
#include "water_vert.spv.h"
#include "water_wire_frag.spv.h"
}  // namespace

std::span<const std::uint32_t> water_vert_spirv() { return pond_spirv_water_vert; }
std::span<const std::uint32_t> water_frag_spirv() { return pond_spirv_water_frag; }
std::span<const std::uint32_t> water_wire_frag_spirv() { return pond_spirv_water_wire_frag; }
std::span<const std::uint32_t> land_vert_spirv() { return pond_spirv_land_vert; }
std::span<const std::uint32_t> land_frag_spirv() { return pond_spirv_land_frag; }
std::span<const std::uint32_t> water_reflect_frag_spirv() { return pond_spirv_water_reflect_frag; }
std::span<const std::uint32_t> land_mirror_vert_spirv() { return pond_spirv_land_mirror_vert; }
std::span<const std::uint32_t> land_mirror_frag_spirv() { return pond_spirv_land_mirror_frag; }
std::span<const std::uint32_t> land_submerged_frag_spirv() { return pond_spirv_land_submerged_frag; }
std::span<const std::uint32_t> land_submerged_vert_spirv() { return pond_spirv_land_submerged_vert; }
std::span<const std::uint32_t> sky_vert_spirv() { return pond_spirv_sky_vert; }
std::span<const std::uint32_t> sky_frag_spirv() { return pond_spirv_sky_frag; }
std::span<const std::uint32_t> caustics_comp_spirv() { return pond_spirv_caustics_comp; }

}  // namespace pond::render
