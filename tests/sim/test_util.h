#pragma once
// Helpers for the solver tests: scenes built in code and runs of the CPU solver.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/cpu_solver.h"
#include "scene/scene.h"

namespace pond::test {

inline scene::Scene grid_scene(int rows, int cols, sim::NodeKind border = sim::NodeKind::fixed) {
  scene::Scene s;
  s.grid.rows = rows;
  s.grid.cols = cols;
  s.border = border;
  return s;
}

inline sim::Perturbation splash(double row, double col, double radius = 2.0, double amplitude = 1.0,
                                std::int64_t step = 0,
                                sim::PerturbTarget target = sim::PerturbTarget::velocity,
                                sim::PerturbMode mode = sim::PerturbMode::add) {
  sim::Perturbation p;
  p.step = step;
  p.row = row;
  p.col = col;
  p.radius = radius;
  p.amplitude = amplitude;
  p.target = target;
  p.mode = mode;
  return p;
}

// The CPU backends this machine runs (compiled in, supported, not masked).
inline std::vector<sim::Backend> available_backends() {
  std::vector<sim::Backend> out;
  for (sim::Backend b : sim::kBackends)
    if (sim::cpu_supports(b)) out.push_back(b);
  return out;
}

inline sim::WaterState run(const scene::Scene& scene, std::int64_t steps,
                           sim::Backend backend = sim::Backend::scalar, int threads = 1,
                           sim::MathMode math = sim::MathMode::exact) {
  sim::CpuSolver solver(sim::build_model(scene, math), backend, threads);
  solver.advance(steps);
  return solver.state();
}

// A floating ball at `position` (world units) of `density` relative to water.
inline sim::BodySpec ball(std::array<double, 3> position, double radius, double density,
                          std::array<double, 3> velocity = {}) {
  sim::BodySpec b;
  b.motion = sim::BodyMotion::floating;
  b.position = position;
  b.velocity = velocity;
  b.radius = radius;
  b.density = density;
  return b;
}

// A kinematic sphere of `radius` moved along `path` (world units).
inline sim::BodySpec kinematic(double radius, std::vector<sim::PathKey> path) {
  sim::BodySpec b;
  b.motion = sim::BodyMotion::kinematic;
  b.radius = radius;
  b.path = std::move(path);
  return b;
}

inline std::size_t node(const scene::Scene& s, int i, int j) {
  return static_cast<std::size_t>(i) * s.grid.cols + j;
}

}  // namespace pond::test
