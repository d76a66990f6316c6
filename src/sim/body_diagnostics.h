#pragma once
// The floating bodies' energy in world units and double precision (the float laws are in
// shaders/shared/body_*.h), for the energy bound the tests hold the contacts to.
#include "sim/model.h"
#include "sim/state.h"

namespace pond::sim {

// Kinetic energy, M g y and buoyancy's potential rho_w g integral(V_sub) of the floating bodies
// (the potential measured against the water level each reads now: its kernel's mean height).
double body_energy(const WaterState& state, const WaterModel& model);

}  // namespace pond::sim
