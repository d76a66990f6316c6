#pragma once
// Applying a tabulated perturbation (model.h) to a CPU state: w added to or written into the y
// velocity or y position of each listed node.
#include "sim/model.h"
#include "sim/state.h"
#include "sim/tile_bounds.h"

namespace pond::sim {

void apply_perturbation(const PerturbationTable& table, WaterState& state);

// The smallest rectangle of nodes holding every node of a non-empty table, on a grid of `cols` columns.
NodeRect node_rect(const PerturbationTable& table, int cols);

}  // namespace pond::sim
