#include "lod/rippled_states.h"

#include <cmath>
#include <random>

#include "sim/cpu_solver.h"
#include "scene/scene.h"

namespace pond::lod_test {

std::vector<float> simulated_pond(int rows, int cols, int drops, int per_step, int settle,
                                  std::uint32_t seed, double amplitude) {
  scene::Scene scene;
  scene.grid = {rows, cols, 1.0};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> row(1, rows - 2), col(1, cols - 2), amp(0.3 * amplitude, amplitude),
      radius(1.0, 2.0);
  const int steps_raining = (drops + per_step - 1) / per_step;
  for (int k = 0; k < drops; ++k) {
    sim::Perturbation p;
    p.step = k / per_step;
    p.row = row(rng), p.col = col(rng), p.radius = radius(rng), p.amplitude = amp(rng);
    scene.perturbations.push_back(p);
  }
  sim::CpuSolver solver(sim::build_model(scene), sim::Backend::scalar, 1);
  solver.advance(steps_raining + settle);
  return sim::to_world_interleaved(solver.state(), solver.model());
}

std::vector<float> analytic_ripples(int rows, int cols, int waves, double amplitude,
                                    std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  struct Wave { double r, c, k, phase, decay, a; };
  std::vector<Wave> w;
  for (int k = 0; k < waves; ++k)
    w.push_back({u(rng) * (rows - 1), u(rng) * (cols - 1), 0.4 + 1.2 * u(rng), 6.3 * u(rng),
                 0.02 + 0.1 * u(rng), amplitude * (0.3 + 0.7 * u(rng))});
  std::vector<float> s(static_cast<std::size_t>(rows) * cols * 6, 0.0f);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      double y = 0, sx = 0, sz = 0;
      for (const Wave& v : w) {
        const double di = i - v.r, dj = j - v.c, r = std::sqrt(di * di + dj * dj) + 1e-9;
        const double env = v.a * std::exp(-v.decay * r);
        y += env * std::cos(v.k * r - v.phase);
        // Horizontal sway along the radius, a quarter period behind (as in Gerstner waves).
        const double side = 0.3 * env * std::sin(v.k * r - v.phase);
        sx += side * dj / r, sz += side * di / r;
      }
      float* n = &s[(static_cast<std::size_t>(i) * cols + j) * 6];
      n[0] = static_cast<float>(j + sx), n[1] = static_cast<float>(y), n[2] = static_cast<float>(i + sz);
    }
  return s;
}

std::vector<float> flat_pond(int rows, int cols, double spacing) {
  std::vector<float> s(static_cast<std::size_t>(rows) * cols * 6, 0.0f);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      float* n = &s[(static_cast<std::size_t>(i) * cols + j) * 6];
      n[0] = static_cast<float>(j * spacing), n[2] = static_cast<float>(i * spacing);
    }
  return s;
}

}  // namespace pond::lod_test
