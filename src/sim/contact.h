#pragma once
// The bodies' contact after a substep, on the CPU: the laws of shaders/shared/body_*.h in the same
// order and with the same roundings as water_contact.comp (shared/bodies.h gives the order).
#include <cstdint>

#include "sim/model.h"
#include "sim/state.h"
#include "sim/tile_bounds.h"

namespace pond::sim {

// Moves the bodies through substep `substep` of step `step` and resolves their contacts with the
// water of `state` (the state after that substep's integration), each other and the land. `reach`
// bounds every node's |ux| and |uz| (the step kernel's; horizontal_reach() computes it from a
// state). With `moved`, appends to it the rectangles of nodes whose displacement it may have changed.
void resolve_contacts(WaterState& state, const WaterModel& model, std::int64_t step, int substep, float reach,
                      std::vector<NodeRect>* moved = nullptr);

// The contact's constants of a model that do not depend on the GPU's layout (the GPU solver adds
// pitch, stride and the schedule's entry).
shared::ContactPush contact_push(const WaterModel& model);

// The largest |ux| or |uz| of any node of `state` (what the step kernels track while they step).
float horizontal_reach(const WaterState& state);

}  // namespace pond::sim
