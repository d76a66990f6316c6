#pragma once
// WaterModel: everything a solver (CPU or GPU) needs, derived once from the WaterSpec of a scene. Solvers work in
// grid units: positions divided by the spacing h, so node (i, j) rests at (j, 0, i) exactly and an
// edge spring's rest length is 1. Hooke's law is homogeneous of degree one in length, so the motion
// in grid units is the world motion divided by h; the state is scaled back on output.
#include <cstdint>
#include <utility>
#include <vector>

#include "sim/bodies.h"
#include "sim/water_spec.h"

namespace pond::sim {

enum class MathMode { exact, fast };

// The constants of one substep, as floats rounded once from double here, so the CPU and the GPU use
// the same bits. With G the sum of (x_b - x_a) * factor over a node's springs:
//   v' = v + (G * kc - v * kd);   x' = x + v' * dt
// which is semi-implicit (symplectic) Euler with a = (c G - gamma v) / m folded into two products.
struct StepConstants {
  float kc = 0;         // c * dt / m
  float kd = 0;         // gamma * dt / m
  float dt = 0;         // substep length
  float rest_edge = 1;  // rest length of edge springs (grid units), calibrated, see model.cpp
  float rest_diag = 1;  // rest length of diagonal springs
  int rsqrt_steps = 3;  // Newton steps of the reciprocal square root
};

// A perturbation's weights precomputed at grid spacing, as the paper does: the nodes within
// 3 * radius of its centre that are not fixed, and the weight of each (already in grid units).
struct PerturbationTable {
  std::int64_t step = 0;
  PerturbTarget target = PerturbTarget::velocity;
  PerturbMode mode = PerturbMode::add;
  std::vector<std::uint32_t> nodes;  // row * cols + col
  std::vector<float> weights;
};

struct WaterModel {
  int rows = 0, cols = 0;
  float spacing = 1;
  int substeps = 1;
  MathMode math = MathMode::exact;
  StepConstants constants;
  Physics physics;                      // the scene's values, for diagnostics
  BasinSpec basin;                      // the floor and the land's height (world units)
  std::vector<std::uint8_t> kinds;      // NodeKind per node, row-major
  std::vector<std::uint32_t> land;      // the land cells' runs (sim/basin.h), for the bodies
  std::vector<PerturbationTable> perturbations;  // sorted by step, scene order within a step
  std::vector<BodyModel> bodies;                 // scene order: the contact's order

  std::size_t nodes() const { return static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols); }
};

WaterModel build_model(const WaterSpec& water, MathMode math = MathMode::exact);

// The node kinds of a scene's water, row-major: the border kind on every border node, then the
// constraint rectangles; fixed wins over vertical.
std::vector<std::uint8_t> node_kinds(const WaterSpec& water);

// A rest length L such that 1 - L * rsqrt(l2) is exactly 0 for the rest squared length l2, so that
// a grid at rest stays at rest bit for bit (the approximate rsqrt is not exactly 1/sqrt).
float calibrated_rest_length(float nominal, float rest_l2, int rsqrt_steps);
// The same for a reciprocal square root accurate to rounding: the GPU's fast mode, the device's
// inversesqrt refined by a Newton step. (Rest lengths calibrated for the CPU's fast rsqrt, which
// errs by up to 4.7e-6, would leave every spring of the GPU's that much tension at rest.)
float calibrated_rest_length_accurate(float nominal, float rest_l2);
// The rest lengths (edge, diagonal) the GPU's step uses for `model`: its constants in exact mode,
// calibrated for the accurate rsqrt in fast mode.
std::pair<float, float> gpu_rest_lengths(const WaterModel& model);

PerturbationTable tabulate(const Perturbation& p, const WaterModel& model);

}  // namespace pond::sim
