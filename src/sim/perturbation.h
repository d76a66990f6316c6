#pragma once
// Applying a tabulated perturbation (model.h) to a CPU state: w added to or written into the y
// velocity or y position of each listed node.
#include "sim/model.h"
#include "sim/state.h"

namespace pond::sim {

void apply_perturbation(const PerturbationTable& table, WaterState& state);

}  // namespace pond::sim
