#pragma once
// The caustics map's geometry (no Vulkan; render/caustics_pass.h draws the map): the grid of sun
// rays the compute pass traces, the map's size, the push constants of its dispatch, and how the
// water's fragment shader finds a floor point's texel (shared/caustics.h).
#include <array>
#include <cstdint>

#include "shared/caustics.h"
#include "sim/model.h"

namespace pond::view {

struct GridSize {
  std::uint32_t width = 0, height = 0;  // columns, rows
};

// The rays' grid for a rows x cols grid of nodes: every node up to kCausticsRays + 1 nodes, else
// every k-th for the smallest k that keeps at most kCausticsRays cells.
GridSize caustics_rays(int rows, int cols);
// The map's size: whole texels per cell of the rays' grid, at most kCausticsTexels along the longer
// side (or one a cell).
GridSize caustics_extent(int rows, int cols);

// The direct sun's share of the floor's light for a sun toward `sun` (unit vector):
// shared/caustics.h's kFloorAmbient split.
float caustics_direct_share(const std::array<double, 3>& sun);

// The push constants for a frame: `sun` the unit direction toward the sun, `floor_depth` world
// units below rest, the state's layout.
shared::caustics::CausticsPush caustics_push(const sim::WaterModel& model, const std::array<double, 3>& sun,
                                             double floor_depth, std::uint32_t stride, std::uint32_t pitch);

// How water.frag finds a world point's texel: uv = p.xz * (x, y) + p.y * (z, w) (WaterFrame::caustics).
std::array<float, 4> caustics_lookup(const sim::WaterModel& model, const std::array<double, 3>& sun);

}  // namespace pond::view
