#pragma once
// The land around and inside the pond (sim/basin.h: the model's basin over its node kinds), drawn.
//  - islands: every grid cell whose four corner nodes are fixed is land, its top at land_height;
//    where land meets water a wall goes down to the floor (so the shoreline is where the water
//    surface cuts the wall);
//  - the rim: walls along the grid's border from land_height down to the floor, facing inwards,
//    and flat land around the pond out to 4x its size (the horizon is the sky, not the void).
// The pool floor itself is not geometry: the water shader traces its refracted rays to it.
// A triangle list (no indices), O(rows + cols + island perimeter) triangles, built once.
#include <array>
#include <vector>

#include "shared/water_render.h"
#include "sim/model.h"
#include "view/sun_shadow.h"

namespace pond::view {

using LandVertex = shared::water_render::LandVertex;  // static_asserts: render/render_layout.h

std::vector<LandVertex> build_land_mesh(const sim::WaterModel& model);

// The box the sky is drawn on (shaders/sky.vert): walls standing on the land's outer edge, from
// land_height up to a lid 1.5 pond sizes higher, so it covers exactly what lies past the land.
struct SkyBox {
  std::array<double, 3> lo, hi;
};
SkyBox sky_box(const sim::WaterModel& model);

// What of a build_land_mesh() mesh the planar reflection mirrors (render/reflection_pass.h): the
// walls' triangles at or above the water's rest plane y = 0 (the walls are cut there, so nothing
// below the water is kept and no fragment needs discarding). The flat tops are left out: a ray
// reflected up from the water meets a wall before it could reach a top, and then only from below,
// so no top is ever seen in the water, and they would cover most of the reflection's target.
std::vector<LandVertex> mirrored_walls(const std::vector<LandVertex>& mesh);

// What of it clear water shows below the surface (render/submerged_pass.h): the islands' walls
// below y = 0. The rim's walls are left out: water.frag traces its rays to them itself.
std::vector<LandVertex> submerged_walls(const std::vector<LandVertex>& mesh, const sim::WaterModel& model);

// The bounding boxes of a triangle list's triangles, every two that touch or overlap merged until
// none do: one box per island for its walls.
std::vector<ShadowCaster> touching_boxes(const std::vector<LandVertex>& triangles);

}  // namespace pond::view
