#pragma once
// What the bodies hold, in world units and double precision (the float laws are in
// shaders/shared/body_*.h): the water level a floating body reads, its submerged fraction, and its
// energy (kinetic, gravity's and buoyancy's potentials), for tests and diagnostics.
#include <cstddef>

#include "sim/model.h"
#include "sim/state.h"

namespace pond::sim {

// The water level under body `b` (world y): the tent kernel's weighted mean height of the nodes
// that are not fixed (shared/body_water.h); NaN where there is no water under it.
double water_level(const WaterState& state, const WaterModel& model, std::size_t b);

// The part of body b's volume below `level` (world y), in [0, 1].
double submerged_fraction(const WaterState& state, const WaterModel& model, std::size_t b, double level);

// Kinetic energy, M g y and buoyancy's potential rho_w g integral(V_sub) of the floating bodies
// (the potential measured against the level each reads now).
double body_energy(const WaterState& state, const WaterModel& model);

}  // namespace pond::sim
