#include "view/caustics_grid.h"

#include <algorithm>
#include <cmath>

namespace pond::view {
namespace {

namespace cs = shared::caustics;

// Where calm water's refracted sun ray lands, per unit of depth (grid units): refract(-sun, +y)
// has xz = -sun.xz / ior and y = -sqrt(1 - (1 - sun.y^2) / ior^2).
std::array<double, 2> calm_offset_per_depth(const std::array<double, 3>& sun) {
  const double eta = 1.0 / cs::kWaterIor;
  const double down = std::sqrt(std::max(1.0 - eta * eta * (1.0 - sun[1] * sun[1]), 1e-6));
  return {-eta * sun[0] / down, -eta * sun[2] / down};
}

}  // namespace

GridSize caustics_rays(int rows, int cols) {
  auto side = [](int nodes) {
    const int cells = std::max(nodes - 1, 1);
    const int every = (cells + cs::kCausticsRays - 1) / cs::kCausticsRays;  // nodes per ray
    return static_cast<std::uint32_t>((cells + every - 1) / every + 1);
  };
  return {side(cols), side(rows)};
}

GridSize caustics_extent(int rows, int cols) {
  const GridSize rays = caustics_rays(rows, cols);
  const std::uint32_t cells = std::max(rays.width, rays.height) - 1;
  const std::uint32_t per_cell = std::max<std::uint32_t>(1, cs::kCausticsTexels / cells);
  return {(rays.width - 1) * per_cell, (rays.height - 1) * per_cell};
}

float caustics_direct_share(const std::array<double, 3>& sun) {
  const double direct = (1.0 - cs::kFloorAmbient) * std::max(sun[1], 0.0);
  return static_cast<float>(direct / (cs::kFloorAmbient + direct));
}

shared::caustics::CausticsPush caustics_push(const sim::WaterModel& model, const std::array<double, 3>& sun,
                                             double floor_depth, std::uint32_t stride, std::uint32_t pitch) {
  const double depth = floor_depth / model.spacing;  // grid units
  const std::array<double, 2> c = calm_offset_per_depth(sun);
  const GridSize e = caustics_extent(model.rows, model.cols), rays = caustics_rays(model.rows, model.cols);
  shared::caustics::CausticsPush p;
  p.sun = {static_cast<float>(sun[0]), static_cast<float>(sun[1]), static_cast<float>(sun[2]), static_cast<float>(depth)};
  p.light = {static_cast<float>(c[0] * depth), static_cast<float>(c[1] * depth), caustics_direct_share(sun), cs::kMaxFocus};
  p.grid = {static_cast<std::uint32_t>(model.rows), static_cast<std::uint32_t>(model.cols), stride, pitch};
  p.map = {e.width, e.height, rays.width, rays.height};
  p.coarse = {static_cast<float>(model.cols - 1) / static_cast<float>(rays.width - 1),
              static_cast<float>(model.rows - 1) / static_cast<float>(rays.height - 1), 0.0f, 0.0f};
  return p;
}

std::array<float, 4> caustics_lookup(const sim::WaterModel& model, const std::array<double, 3>& sun) {
  // uv = (p.xz / h - c * depth / h) / (cols - 1, rows - 1), depth = -p.y (world), c per unit depth.
  const std::array<double, 2> c = calm_offset_per_depth(sun);
  const double h = model.spacing;
  const double sx = 1.0 / (h * (model.cols - 1)), sz = 1.0 / (h * (model.rows - 1));
  return {static_cast<float>(sx), static_cast<float>(sz), static_cast<float>(c[0] * sx), static_cast<float>(c[1] * sz)};
}

}  // namespace pond::view
