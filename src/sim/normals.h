#pragma once
// Vertex normals from the four edge neighbours (central differences, one-sided at the border):
//   n = normalize((x[i+1][j] - x[i-1][j]) x (x[i][j+1] - x[i][j-1])),
// +y for the surface at rest. Normals are needed once per rendered frame, not once per substep, so
// they are a pass of their own over the final state rather than part of every substep.
#include <vector>

#include "sim/model.h"
#include "sim/solver.h"
#include "sim/state.h"

namespace pond::sim {

struct Normals {
  std::vector<float> x, y, z;
};

Normals compute_normals(const WaterState& state, const WaterModel& model);
// The same from displacements only (sim/solver.h): rows `pitch` nodes apart; out compact.
Normals compute_normals(const HostDisplacements& u, const WaterModel& model);

}  // namespace pond::sim
