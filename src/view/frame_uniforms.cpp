#include "view/frame_uniforms.h"

#include <cmath>
#include <cstring>

#include "view/caustics_grid.h"
#include "view/land_mesh.h"

namespace pond::view {
namespace {

namespace wr = shared::water_render;

// xyz (or rgb) of a uniform vec4; w = 0 (a packed w lane is set by its name: POND_FRAME_*).
wr::vec4 v4(const std::array<double, 3>& a) {
  return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2]), 0.0f};
}

}  // namespace

wr::WaterFrame frame_uniforms(const FrameUniformsInput& in) {
  const sim::WaterModel& model = in.model;
  const LightingSpec& l = in.lighting;
  const std::array<double, 3> sun = unit(l.sun);
  wr::WaterFrame f;
  std::memcpy(f.view_proj.m, in.view_proj.data(), sizeof f.view_proj.m);
  f.eye = v4(in.camera.eye);
  POND_FRAME_GRID_SPACING(f) = model.spacing;
  f.sun = v4(sun);
  f.sky = v4(l.sky);
  f.water = v4(l.water);
  f.absorption = v4(l.absorption);
  f.ground = v4(l.ground);
  POND_FRAME_FLOOR_DEPTH(f) = static_cast<float>(model.basin.floor_depth);
  POND_FRAME_LAND_HEIGHT(f) = static_cast<float>(model.basin.land_height);
  f.wire = {0.02f, 0.05f, 0.08f, 0.55f};
  POND_FRAME_ROWS(f) = static_cast<std::uint32_t>(model.rows);
  POND_FRAME_COLS(f) = static_cast<std::uint32_t>(model.cols);
  POND_FRAME_STATE_STRIDE(f) = in.stride;
  POND_FRAME_STATE_PITCH(f) = in.pitch;
  const SkyBox sky = sky_box(model);
  f.sky_lo = v4(sky.lo);
  f.sky_hi = v4(sky.hi);
  f.screen = {1.0f / static_cast<float>(in.camera.width), 1.0f / static_cast<float>(in.camera.height), kReflectionShift,
              0.0f};
  if (in.shadow) std::memcpy(f.shadow.m, in.shadow->texture.data(), sizeof f.shadow.m);
  const std::array<float, 3> under_water = sunlight_in_water(l.sun);
  f.shadow_sun = {under_water[0], under_water[1], under_water[2], 0.0f};
  const std::array<float, 4> c = caustics_lookup(model, sun);
  f.caustics = {c[0], c[1], c[2], c[3]};
  const GridSize map = caustics_extent(model.rows, model.cols);
  f.caustics_size = {map.width, map.height, 0, 0};
  return f;
}

}  // namespace pond::view
