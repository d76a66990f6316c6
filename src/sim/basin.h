#pragma once
// The solid the water lies in (sim::BasinSpec: the floor, the land's height) over the node kinds:
// one declaration for the picture (view/land_mesh.h) and the bodies (shared/body_motion.h).
// Grid cell (i, j) spans nodes i..i+1, j..j+1; it is land when its four corner nodes are fixed.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/water_spec.h"

namespace pond::sim {

// Whether cell (i, j) is land, from the row-major node kinds of a grid `cols` wide.
bool land_cell(const std::vector<std::uint8_t>& kinds, int cols, int i, int j);

// The land cells as runs per row of cells, in the layout the bodies' contact reads
// (shared/bodies.h, POND_CONTACT_BINDING_LAND).
std::vector<std::uint32_t> land_runs(const std::vector<std::uint8_t>& kinds, int rows, int cols);

// What a sphere at (x, y, z) of radius r (world units) overlaps, if anything: the pool's floor,
// the pond's walls or a land cell ("the pool floor", "the rim", "the land at cell (i, j)").
std::optional<std::string> sphere_in_solid(const std::vector<std::uint8_t>& kinds, const GridSpec& grid,
                                           const BasinSpec& basin, const std::array<double, 3>& centre,
                                           double radius);

}  // namespace pond::sim
