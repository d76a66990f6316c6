#pragma once
// The scene file's "bodies" entries (sim::BodySpec), parsed and checked against the grid.
#include <cstddef>
#include <optional>

#include "scene/json_fields.h"
#include "scene/scene.h"
#include "sim/water_spec.h"

namespace pond::scene {

inline constexpr std::size_t kMaxBodies = 64;

// One entry of "bodies": its shape, motion, radius (at least the grid spacing), a floating body's
// mass, position and velocity, a kinematic body's path; every position over the grid.
sim::BodySpec parse_body(JsonFields f, const sim::GridSpec& grid);

// What is wrong with a body on this grid, if anything (the key under the body: "radius", "mass",
// "position", "path", "path[k]"): a radius below the spacing (a smaller sphere slips between the
// nodes) or above a quarter of the grid's extent, a floating body's mass not positive, a kinematic
// body without a path, a position (a floating body's, every key of a path) not over the grid. The parser and Session::add_body both
// check with it.
std::optional<Problem> body_problem(const sim::BodySpec& body, const sim::GridSpec& grid);

}  // namespace pond::scene
