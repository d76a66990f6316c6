#pragma once
// The scene file's "bodies" entries (sim::BodySpec), parsed and checked against the grid.
#include <cstddef>

#include "scene/json_fields.h"
#include "sim/water_spec.h"

namespace pond::scene {

inline constexpr std::size_t kMaxBodies = 64;

// One entry of "bodies": its shape, motion, radius (at least the grid spacing), a floating body's
// mass, position and velocity, a kinematic body's path; every position over the grid.
sim::BodySpec parse_body(JsonFields f, const sim::GridSpec& grid);

}  // namespace pond::scene
