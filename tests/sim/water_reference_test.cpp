// The CPU solver against an independent float64 model of the spec (water_reference.h, which shares
// no code with src/sim): on a few scenes, stepped in lockstep, every node's world position and
// velocity stay within a stated bound of the model's; and the vertex normals equal the spec's
// float64 formula evaluated on the solver's own positions.
//
// The bound. The solver is float32 (positions kept as displacements from rest, grid units), with a
// reciprocal square root of 3 Newton steps and rest lengths calibrated to it; the model is float64
// with a true square root. A float32 step rounds each of the ~60 operations a node takes at a
// relative 6e-8: about 1e-7 of the largest displacement A a step, and over N steps of a stable
// wave near rest (errors add up, they do not grow exponentially) about N * 1e-7 * A.
// kToleranceRelPerStep allows ten times that: 1e-6 * A a step, over the scenes' 150 to 300 steps.
// (Far from rest, a free or pre-tensioned sheet folding over, float32 and float64 part ways
// exponentially: chaos, not a bug; so the scenes stay near rest.) A wrong physics term moves nodes
// by a fixed fraction of A within a few steps: a damping or stiffness off by a few per cent, a
// missing diagonal spring, explicit instead of symplectic Euler, the Gaussian's 2 r^2 as r^2, a
// cutoff at 4 r instead of 3 r (a weight of exp(-4.5) = 1.1 % of the amplitude), a vertical-only
// node moving sideways.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "scene/scene.h"
#include "sim/cpu_solver.h"
#include "sim/model.h"
#include "sim/normals.h"
#include "sim/water_reference.h"

namespace pond::sim {
namespace {

using reference::Kind;
using reference::Pond;
using reference::Rect;
using reference::Splash;

// Allowed error per step, relative to the largest displacement of the run (see above).
constexpr double kToleranceRelPerStep = 1e-6;

struct Case {
  const char* name;
  Pond pond;
  std::int64_t steps;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> cases() {
  std::vector<Case> all;
  {  // The paper's grid and Table 1, a fixed shore, an island, a velocity splash beside it.
    Pond p;
    p.constraints = {{Kind::fixed, 30, 35, 30, 36}};
    p.splashes = {{0, 25, 26.5, 2.0, 1.0, false, false}};
    all.push_back({"paper_50x50_island", p, 300});
  }
  {  // A rectangle at spacing 0.5, walls vertical-only, an island and a vertical-only strip inside,
     // substeps, every perturbation kind at fractional centres, two of them at one step.
    Pond p;
    p.rows = 31, p.cols = 45, p.spacing = 0.5, p.substeps = 2, p.border = Kind::vertical;
    p.constraints = {{Kind::vertical, 5, 25, 36, 37}, {Kind::fixed, 10, 14, 12, 16}, {Kind::vertical, 12, 13, 15, 20}};
    p.splashes = {{0, 20.5, 22.25, 1.5, 0.8, false, false},
                  {3, 6, 8.5, 1.0, -0.3, true, false},
                  {3, 6.5, 9, 1.0, 0.25, true, true},
                  {40, 24, 30, 2.0, 0.4, false, true},
                  {90, 0.5, 44, 1.5, 0.5, true, false}};
    all.push_back({"rect_31x45_vertical_walls", p, 250});
  }
  {  // A free border, no damping, other mass, stiffness and dt.
    Pond p;
    p.rows = 23, p.cols = 17, p.mass = 2.5, p.stiffness = 5.0, p.damping = 0.0, p.dt = 0.3;
    p.border = Kind::free;
    p.splashes = {{0, 11, 8, 2.5, 0.3, false, false}, {20, 3, 3, 1.0, 0.1, true, false}};
    all.push_back({"free_23x17_undamped", p, 150});
  }
  {  // Springs pre-tensioned (rest length 0.9 h) in a fixed frame.
    Pond p;
    p.rows = 29, p.cols = 21, p.damping = 0.02, p.rest_ratio = 0.9;
    p.splashes = {{0, 14, 10, 2.0, 0.7, false, false}, {50, 7.5, 15, 1.5, 0.3, true, true}};
    all.push_back({"pretension_29x21", p, 300});
  }
  {  // Every node vertical-only: waves pass through each other.
    Pond p;
    p.rows = 40, p.cols = 40, p.border = Kind::vertical;
    p.constraints = {{Kind::vertical, 0, 39, 0, 39}};
    p.splashes = {{0, 12, 12, 2.0, 1.0, false, false}, {0, 27, 27, 2.0, -1.0, false, false}};
    all.push_back({"all_vertical_40x40", p, 200});
  }
  return all;
}

struct Compared {
  double max_error = 0;      // world units, positions and velocities (times dt) over every step
  double amplitude = 0;      // the model's largest displacement from rest over the run
  std::int64_t worst_step = 0;
  std::size_t worst_node = 0;
};

std::array<double, 3> solver_position(const WaterState& s, std::size_t n, int cols, double h) {
  const double i = static_cast<double>(n / static_cast<std::size_t>(cols)), j = static_cast<double>(n % static_cast<std::size_t>(cols));
  return {(j + s.ux[n]) * h, s.uy[n] * h, (i + s.uz[n]) * h};
}

Compared run_both(const Case& c) {
  const scene::Scene scene = scene::parse_scene(reference::scene_json(c.pond), c.name);
  CpuSolver solver(build_model(scene), Backend::scalar, 1);
  reference::Water model(c.pond);
  const double h = c.pond.spacing, dt = c.pond.dt;
  const int cols = c.pond.cols;
  Compared out;
  for (std::int64_t step = 1; step <= c.steps; ++step) {
    solver.advance(1);
    model.step();
    const WaterState& s = solver.state();
    for (std::size_t n = 0; n < s.nodes(); ++n) {
      const reference::Node& r = model.nodes()[n];
      const auto p = solver_position(s, n, cols, h);
      const double i = static_cast<double>(n / static_cast<std::size_t>(cols)), j = static_cast<double>(n % static_cast<std::size_t>(cols));
      out.amplitude = std::max({out.amplitude, std::fabs(r.x - j * h), std::fabs(r.y), std::fabs(r.z - i * h)});
      // Velocities times dt: the displacement they make in a step, comparable with positions.
      const double e = std::max({std::fabs(p[0] - r.x), std::fabs(p[1] - r.y), std::fabs(p[2] - r.z),
                                 std::fabs(s.vx[n] * h - r.vx) * dt, std::fabs(s.vy[n] * h - r.vy) * dt,
                                 std::fabs(s.vz[n] * h - r.vz) * dt});
      if (e > out.max_error) out.max_error = e, out.worst_step = step, out.worst_node = n;
    }
  }
  return out;
}

class WaterReference : public ::testing::TestWithParam<Case> {};

TEST_P(WaterReference, SolverFollowsTheFloat64ModelOfTheSpec) {
  const Case& c = GetParam();
  const Compared r = run_both(c);
  const double bound = kToleranceRelPerStep * static_cast<double>(c.steps) * r.amplitude;
  std::printf("%s: %lld steps, largest displacement %.4g, largest difference %.3g (%.3g of it; bound %.3g) "
              "at step %lld, node %zu\n",
              c.name, static_cast<long long>(c.steps), r.amplitude, r.max_error, r.max_error / r.amplitude, bound,
              static_cast<long long>(r.worst_step), r.worst_node);
  EXPECT_GT(r.amplitude, 0.05) << "the scene must move";
  EXPECT_LE(r.max_error, bound) << c.name << ": step " << r.worst_step << ", node " << r.worst_node;
}

INSTANTIATE_TEST_SUITE_P(Scenes, WaterReference, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& p) { return std::string(p.param.name); });

// The solver's normals (src/sim/normals.cpp) against the spec's formula in float64 on the solver's
// own positions, on a scene whose surface is tilted every way (and at every border kind). float32
// positions near 1 and a 3-step rsqrt give about 1e-6; a swapped cross product gives -n, a wrong
// neighbour or a missing rest offset an error of order one.
TEST(WaterReferenceNormals, NormalsFollowTheSpecsFormula) {
  for (const Case& c : cases()) {
    const scene::Scene scene = scene::parse_scene(reference::scene_json(c.pond), c.name);
    CpuSolver solver(build_model(scene), Backend::scalar, 1);
    solver.advance(30);
    const WaterState& s = solver.state();
    const Normals n = compute_normals(s, solver.model());
    const int rows = c.pond.rows, cols = c.pond.cols;
    std::vector<std::array<double, 3>> x;
    for (std::size_t k = 0; k < s.nodes(); ++k) x.push_back(solver_position(s, k, cols, c.pond.spacing));
    double worst = 0, tilt = 0;
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) {
        const auto want = reference::normal(x, rows, cols, i, j);
        const std::size_t k = static_cast<std::size_t>(i) * cols + j;
        worst = std::max({worst, std::fabs(n.x[k] - want[0]), std::fabs(n.y[k] - want[1]), std::fabs(n.z[k] - want[2])});
        tilt = std::max(tilt, std::hypot(want[0], want[2]));
      }
    std::printf("%s: normals within %.3g of the formula, largest tilt %.3g\n", c.name, worst, tilt);
    EXPECT_GT(tilt, 0.05) << c.name << ": a flat surface proves little";
    EXPECT_LT(worst, 1e-5) << c.name;
  }
}

}  // namespace
}  // namespace pond::sim
