#include "gpu/shaders.h"

namespace pond::gpu {
namespace {
#include "water_contact_comp.spv.h"
#include "water_contact_denorm_comp.spv.h"
#include "water_gather_comp.spv.h"
#include "water_normals_comp.spv.h"
#include "water_normals_denorm_comp.spv.h"
#include "water_normals_tiles_comp.spv.h"
#include "water_normals_tiles_denorm_comp.spv.h"
#include "water_perturb_comp.spv.h"
#include "water_perturb_denorm_comp.spv.h"
#include "water_step_comp.spv.h"
#include "water_step_denorm_comp.spv.h"
#include "water_step_int64_comp.spv.h"
#include "water_step_int64_denorm_comp.spv.h"
#include "water_tiles_comp.spv.h"
#include "water_tiles_denorm_comp.spv.h"
}  // namespace

std::span<const std::uint32_t> water_step_spirv(bool int64_stores, bool denorm_preserve) {
  if (int64_stores && denorm_preserve) return pond_spirv_water_step_int64_denorm_comp;
  if (int64_stores) return pond_spirv_water_step_int64_comp;
  if (denorm_preserve) return pond_spirv_water_step_denorm_comp;
  return pond_spirv_water_step_comp;
}
std::span<const std::uint32_t> water_perturb_spirv(bool denorm_preserve) {
  if (denorm_preserve) return pond_spirv_water_perturb_denorm_comp;
  return pond_spirv_water_perturb_comp;
}
std::span<const std::uint32_t> water_normals_spirv(bool denorm_preserve) {
  if (denorm_preserve) return pond_spirv_water_normals_denorm_comp;
  return pond_spirv_water_normals_comp;
}
std::span<const std::uint32_t> water_normals_tiles_spirv(bool denorm_preserve) {
  if (denorm_preserve) return pond_spirv_water_normals_tiles_denorm_comp;
  return pond_spirv_water_normals_tiles_comp;
}
std::span<const std::uint32_t> water_tiles_spirv(bool denorm_preserve) {
  if (denorm_preserve) return pond_spirv_water_tiles_denorm_comp;
  return pond_spirv_water_tiles_comp;
}

std::span<const std::uint32_t> water_contact_spirv(bool denorm_preserve) {
  if (denorm_preserve) return pond_spirv_water_contact_denorm_comp;
  return pond_spirv_water_contact_comp;
}

std::span<const std::uint32_t> water_gather_spirv() { return pond_spirv_water_gather_comp; }

}  // namespace pond::gpu
