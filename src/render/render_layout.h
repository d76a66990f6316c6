#pragma once
// The C++ view of shaders/shared/water_render.h: pins the std140 uniform block and the land vertex
// layout, so a change on one side cannot silently disagree with the other.
#include <cstddef>

#include "shared/water_render.h"

namespace pond::render {

using shared::water_render::LandVertex;
using shared::water_render::WaterFrame;

static_assert(sizeof(WaterFrame) == 368);
static_assert(offsetof(WaterFrame, view_proj) == 0 && offsetof(WaterFrame, eye) == 64 &&
              offsetof(WaterFrame, sun) == 80 && offsetof(WaterFrame, sky) == 96 &&
              offsetof(WaterFrame, water) == 112 && offsetof(WaterFrame, ground) == 128 &&
              offsetof(WaterFrame, pool) == 144 && offsetof(WaterFrame, wire) == 160);
static_assert(offsetof(WaterFrame, grid) == 160 + 16 && offsetof(WaterFrame, sky_lo) == 192 &&
              offsetof(WaterFrame, sky_hi) == 208 && offsetof(WaterFrame, screen) == 224 &&
              offsetof(WaterFrame, shadow) == 240 && offsetof(WaterFrame, shadow_sun) == 304 &&
              offsetof(WaterFrame, caustics_size) == 320 && offsetof(WaterFrame, caustics) == 336 &&
              offsetof(WaterFrame, absorption) == 352);
static_assert(sizeof(LandVertex) == 32 && offsetof(LandVertex, normal) == 16);

}  // namespace pond::render
