#pragma once
// The land around and inside the pond, from the node kinds: what the water is held by.
//  - islands: every grid cell whose four corner nodes are fixed is land, its top at land_height;
//    where land meets water a wall goes down to the floor (so the shoreline is where the water
//    surface cuts the wall);
//  - the rim: walls along the grid's border from land_height down to the floor, facing inwards,
//    and flat land around the pond out to 4x its size (the horizon is the sky, not the void).
// The pool floor itself is not geometry: the water shader traces its refracted rays to it.
// A triangle list (no indices), O(rows + cols + island perimeter) triangles, built once.
#include <vector>

#include "shared/water_render.h"
#include "sim/model.h"

namespace pond::view {

using LandVertex = shared::water_render::LandVertex;  // static_asserts: render/render_layout.h

std::vector<LandVertex> build_land_mesh(const sim::WaterModel& model, double floor_depth, double land_height);

// The triangles of a build_land_mesh() mesh that lie at or above the water's rest plane y = 0 (its
// walls are cut there): what the planar reflection mirrors, so its fragment shader need not
// discard (render/reflection_pass.h).
std::vector<LandVertex> above_water(const std::vector<LandVertex>& mesh);

}  // namespace pond::view
