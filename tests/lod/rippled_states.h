#pragma once
// Moving water surfaces for the LOD tests and benchmarks, as STATE.npy-layout floats
// (rows * cols * 6: x, y, z, vx, vy, vz in world units).
#include <cstdint>
#include <vector>

namespace pond::lod_test {

// The spring-mass solver (pond_sim) after `drops` random splashes, `per_step` of them applied
// before each of the last steps, then `settle` more steps: `drops` large = rain over the whole
// pond, small = a few spreading rings. Each splash adds up to `amplitude` (0.3x to 1x of it) to
// the vertical velocity over a Gaussian of radius 1 to 2 nodes.
std::vector<float> simulated_pond(int rows, int cols, int drops, int per_step, int settle,
                                  std::uint32_t seed, double amplitude = 1.0);

// Analytic ripples: a few damped radial waves with random centres, plus a horizontal sway (the
// surface is parametric, nodes move sideways too). Cheap, any size.
std::vector<float> analytic_ripples(int rows, int cols, int waves, double amplitude,
                                    std::uint32_t seed);

// Every node at rest: (col, 0, row) * spacing.
std::vector<float> flat_pond(int rows, int cols, double spacing = 1.0);

}  // namespace pond::lod_test
