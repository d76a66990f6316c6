#pragma once
// An independent float64 model of the water as SPEC.md and ARCHITECTURE.md state it, for the
// tests to hold the solver to: world units, every spring evaluated from both ends, Hooke's force
// c (x_j - x_i)(1 - l_rest / l) with a true square root, a = (F - gamma v) / m, symplectic Euler
// (v first, then x with the new v), fixed and vertical-only constraints, Gaussian perturbations
// applied just before their step. It includes nothing of src/sim: only the standard library.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace pond::reference {

enum class Kind { free, vertical, fixed };

struct Rect {
  Kind kind = Kind::fixed;
  int row0 = 0, row1 = 0, col0 = 0, col1 = 0;  // inclusive
};

struct Splash {
  std::int64_t step = 0;
  double row = 0, col = 0;  // index space, may be fractional
  double radius = 1, amplitude = 1;  // world units
  bool position = false;  // y position, else y velocity
  bool set = false;       // written, else added
};

struct Pond {
  int rows = 50, cols = 50;
  double spacing = 1.0;
  double mass = 4.0, stiffness = 7.0, damping = 0.05, dt = 0.4;
  int substeps = 1;
  double rest_ratio = 1.0;
  Kind border = Kind::fixed;
  std::vector<Rect> constraints;
  std::vector<Splash> splashes;
};

// The same pond as a scene file (the contract's keys), for the solver under test.
std::string scene_json(const Pond& pond);

struct Node {
  double x, y, z, vx, vy, vz;  // world position and velocity
};

class Water {
 public:
  explicit Water(const Pond& pond);
  void step();  // one step of dt: its perturbations, then `substeps` substeps of dt / substeps
  std::int64_t steps() const { return steps_; }
  const std::vector<Node>& nodes() const { return nodes_; }
  Kind kind(int i, int j) const { return kinds_[static_cast<std::size_t>(i) * pond_.cols + j]; }

 private:
  void perturb(const Splash& s);
  void substep(double dt);
  Pond pond_;
  std::vector<Kind> kinds_;
  std::vector<Node> nodes_;
  std::int64_t steps_ = 0;
};

// The spec's vertex normal at (i, j) of world positions (row-major, rows x cols):
// normalize((x[i+1][j] - x[i-1][j]) x (x[i][j+1] - x[i][j-1])), one-sided at the border.
std::array<double, 3> normal(const std::vector<std::array<double, 3>>& positions, int rows, int cols, int i, int j);

}  // namespace pond::reference
