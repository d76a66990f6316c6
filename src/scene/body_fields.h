#pragma once
// The scene file's "bodies" entries (sim::BodySpec), parsed and checked against the water they are
// in: the grid, the physics (the stable densities, the fastest motion) and the basin's solid.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "scene/json_fields.h"
#include "scene/scene.h"
#include "shared/bodies.h"
#include "sim/water_spec.h"

namespace pond::scene {

inline constexpr std::size_t kMaxBodies = shared::kMaxBodies;

// The densities (relative to water) a floating ball of this radius is stable for under `physics`:
// its buoyancy's vertical oscillation must stay well inside the explicit integration's bound.
struct DensityRange {
  double min, max;
};
DensityRange stable_densities(double radius, const sim::Physics& physics);

// One entry of "bodies": its shape, motion, radius, a floating body's density or mass (exactly
// one), position and velocity, a kinematic body's path.
sim::BodySpec parse_body(JsonFields f);

// What is wrong with one body in `water` (whose node kinds are `kinds`), if anything, with the key
// under the body ("radius", "density", "mass", "position", "velocity", "path[k]"):
//  - a radius below the spacing (a smaller sphere slips between the nodes), a diameter over the
//    pond's interior, or (floating) over the pool's depth;
//  - a density (or the density a mass gives) outside stable_densities();
//  - a position off the grid, or (floating) in the floor, the rim or the land, or so high that
//    its fall would pass POND_MAX_SPACINGS_PER_STEP spacings a step; a faster velocity, or a path
//    moving faster.
// The parser and Session::add_body both check with it.
std::optional<Problem> body_problem(const sim::BodySpec& body, const sim::WaterSpec& water,
                                    const std::vector<std::uint8_t>& kinds);

// The first body of `bodies` (placed at `positions`, world units) that overlaps an earlier one
// where at least one of the two floats, with the complaint ("overlaps bodies[k]").
struct Overlap {
  std::size_t index;
  std::string what;
};
std::optional<Overlap> first_overlap(const std::vector<sim::BodySpec>& bodies,
                                     const std::vector<std::array<double, 3>>& positions);

// Where a body of a scene is at step 0 (world units): a floating body's position, the first key of
// a kinematic body's path.
std::array<double, 3> start_position(const sim::BodySpec& body);

}  // namespace pond::scene
