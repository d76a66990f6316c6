#include "gpu/shaders.h"

namespace pond::gpu {
namespace {
#include "water_normals_comp.spv.h"
#include "water_perturb_comp.spv.h"
#include "water_step_comp.spv.h"
#include "water_step_int64_comp.spv.h"
}  // namespace

std::span<const std::uint32_t> water_step_spirv() { return pond_spirv_water_step_comp; }
std::span<const std::uint32_t> water_step_int64_spirv() { return pond_spirv_water_step_int64_comp; }
std::span<const std::uint32_t> water_perturb_spirv() { return pond_spirv_water_perturb_comp; }
std::span<const std::uint32_t> water_normals_spirv() { return pond_spirv_water_normals_comp; }

}  // namespace pond::gpu
