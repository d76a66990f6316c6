#pragma once
// The built-in states `pond bench` measures, the same on every machine: the solver's rippled pond,
// the LOD's rain over the whole pond and its camera, and the bodies' 257² pond.
#include <cstdint>
#include <vector>

#include "lod/camera_budget.h"
#include "sim/model.h"

namespace pond::bench {

// A square pond, fixed shore, five splashes spread over it (bench/sim's BM_Solver's state).
sim::WaterModel rippled_model(int size, sim::MathMode math);
// Steps of one solver sample: about `node_steps` over the grid's nodes, at least 2.
std::int64_t steps_per_sample(int size, double node_steps);
// Steps every solver run takes before its samples, so the splashes have spread.
inline constexpr std::int64_t kWarmSteps = 20;

// Rain over the whole pond (bench/lod's "rain"): one drop per 160 nodes over 20 steps, then 15
// more steps; x, y, z, vx, vy, vz per node in world units. Simulated on this CPU's widest backend.
std::vector<float> rain_state(int side);
// The LOD's camera: 35 units up over the near shore looking across, scaled with the pond, 1280x720.
lod::Camera rain_camera(int side);

// The demo's grid at `side` (257 in the full run): an island, a splash and `bodies` bodies (two
// spheres dragged across, the rest floating balls); bench/gpu's bench_bodies measures it too.
sim::WaterModel bodies_model(int side, int bodies);

}  // namespace pond::bench
