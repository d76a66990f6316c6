#include "app/bench/workloads.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "sim/backends.h"
#include "sim/cpu_solver.h"
#include "sim/state.h"
#include "sim/water_spec.h"

namespace pond::bench {

sim::WaterModel rippled_model(int size, sim::MathMode math) {
  sim::WaterSpec s;
  s.grid.rows = s.grid.cols = size;
  for (int k = 0; k < 5; ++k) {
    sim::Perturbation p;
    p.row = size * (0.2 + 0.15 * k);
    p.col = size * (0.7 - 0.1 * k);
    p.radius = 2.0;
    p.amplitude = 0.5;
    s.perturbations.push_back(p);
  }
  return sim::build_model(s, math);
}

std::int64_t steps_per_sample(int size, double node_steps) {
  return std::max<std::int64_t>(2, std::llround(node_steps / (double(size) * size)));
}

std::vector<float> rain_state(int side) {
  // The recipe of tests/lod/rippled_states.cpp's simulated_pond(side, side, drops, drops / 20, 15, 1, 0.1).
  const int drops = side * side / 160, per_step = std::max(1, drops / 20), settle = 15;
  const double amplitude = 0.1;
  sim::WaterSpec s;
  s.grid.rows = s.grid.cols = side;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> row(1, side - 2), col(1, side - 2), amp(0.3 * amplitude, amplitude),
      radius(1.0, 2.0);
  for (int k = 0; k < drops; ++k) {
    sim::Perturbation p;
    p.step = k / per_step;
    p.row = row(rng), p.col = col(rng), p.radius = radius(rng), p.amplitude = amp(rng);
    s.perturbations.push_back(p);
  }
  sim::CpuSolver solver(sim::build_model(s), sim::best_backend(), 0);  // every backend gives the same bits
  solver.advance((drops + per_step - 1) / per_step + settle);
  return sim::to_world_interleaved(solver.state(), solver.model());
}

lod::Camera rain_camera(int side) {
  const double s = (side - 1) / 256.0;
  return {{128 * s, 35 * s, -20 * s}, {128 * s, 0, 110 * s}, 60, 1280, 720};
}

sim::WaterModel bodies_model(int side, int count) {
  const double s = (side - 1) / 256.0;  // positions scale with the grid
  sim::WaterSpec w;
  w.grid.rows = w.grid.cols = side;
  w.physics.rest_ratio = 0.95;
  w.constraints.push_back({sim::NodeKind::fixed, int(60 * s), int(80 * s), int(150 * s), int(175 * s)});
  w.perturbations.push_back({.step = 0, .row = 128 * s, .col = 90 * s, .radius = 4, .amplitude = 1,
                             .target = sim::PerturbTarget::velocity, .mode = sim::PerturbMode::add});
  if (count == 0) return sim::build_model(w);
  for (int k = 0; k < 2; ++k) {
    sim::BodySpec b;
    b.motion = sim::BodyMotion::kinematic;
    b.radius = 3.0;
    b.path = {{0, {20.0 * s, 0.5, (30.0 + 50 * k) * s}}, {4000, {236.0 * s, 0.5, (40.0 + 50 * k) * s}}};
    w.bodies.push_back(b);
  }
  for (int k = 0; k < count - 2; ++k) {
    const int col = k % 8, row = k / 8;
    sim::BodySpec b;
    b.radius = 2.0 + 0.125 * (k % 9);
    b.density = 0.3 + 0.075 * (k % 9);
    b.position = {(24.0 + 26 * col) * s, col % 3 == 0 ? 3.5 : 0.0, (100.0 + 18 * row) * s};
    b.velocity = {col % 2 == 0 ? 0.5 : -0.5, 0.0, 0.05 * (row % 3 - 1)};
    w.bodies.push_back(b);
  }
  return sim::build_model(w);
}

}  // namespace pond::bench
