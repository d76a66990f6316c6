#pragma once
// The contact between the water and the bodies after a substep, on the CPU: the algorithm of
// shared/bodies.h, in the same order and with the same roundings as water_contact.comp.
#include <cstdint>

#include "sim/model.h"
#include "sim/state.h"

namespace pond::sim {

// Moves the bodies through substep `substep` of step `step` and resolves their contact with the
// water of `state` (the state after that substep's integration). `reach` bounds every node's
// |ux| and |uz| (the step kernel's; horizontal_reach() computes it from a state).
void resolve_contacts(WaterState& state, const WaterModel& model, std::int64_t step, int substep, float reach);

// The largest |ux| or |uz| of any node of `state` (what the step kernels track while they step).
float horizontal_reach(const WaterState& state);

}  // namespace pond::sim
