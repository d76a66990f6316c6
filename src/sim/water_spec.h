#pragma once
// The water as a scene file describes it (world units): the grid, the physics, the constraints and
// the perturbations of the contract in docs/scenes.md. Validated by src/scene; WaterModel is built from it.
#include <array>
#include <cstdint>
#include <vector>

namespace pond::sim {

enum class NodeKind : std::uint8_t { free = 0, vertical = 1, fixed = 2 };
enum class PerturbTarget { velocity, position };
enum class PerturbMode { add, set };

struct GridSpec {
  int rows = 50;
  int cols = 50;
  double spacing = 1.0;  // h
  bool operator==(const GridSpec&) const = default;
};

// Table 1 of the paper, plus substeps (each step of dt is integrated as `substeps` steps of
// dt/substeps) and an optional spring pre-tension (rest length = ratio * h or ratio * h*sqrt(2)).
struct Physics {
  double mass = 4.0;
  double stiffness = 7.0;
  double damping = 0.05;
  double dt = 0.4;
  int substeps = 1;
  double rest_ratio = 1.0;
  double gravity = 0.05;  // world units / time^2, on the floating bodies only (not the membrane)
  double water_density = 1.0;  // mass per unit volume: a floating body's density is relative to it
  double body_drag = 0.05;     // C of the bodies' linear drag, rho_w C A v (world units / time)
  bool operator==(const Physics&) const = default;
};

// The solid the water lies in (world units), for the picture and for the bodies alike: a flat
// floor floor_depth below the rest plane; land land_height above it wherever all four corner nodes
// of a grid cell are fixed (islands) and all around the grid (the rim and the land beyond it).
struct BasinSpec {
  double floor_depth = 3.0;
  double land_height = 1.0;
  bool operator==(const BasinSpec&) const = default;
};

struct ConstraintRect {
  NodeKind kind = NodeKind::fixed;  // fixed or vertical
  int row0 = 0, row1 = 0;           // inclusive
  int col0 = 0, col1 = 0;           // inclusive
  bool operator==(const ConstraintRect&) const = default;
};

struct Perturbation {
  std::int64_t step = 0;  // applied just before integration step number `step` (0-based)
  double row = 0, col = 0;
  double radius = 1.0;  // world units
  double amplitude = 1.0;
  PerturbTarget target = PerturbTarget::velocity;
  PerturbMode mode = PerturbMode::add;
  bool operator==(const Perturbation&) const = default;
};

// A body in the water (world units; node (i, j) rests at (j h, 0, i h), y up). Kinematic: follows
// `path` and is not moved by the water; floating: a mass under gravity that the water supports.
enum class BodyShape { sphere };
enum class BodyMotion { kinematic, floating };
struct PathKey {
  std::int64_t step = 0;  // the position at the start of this step; piecewise linear between keys
  std::array<double, 3> position{};
  bool operator==(const PathKey&) const = default;
};
struct BodySpec {
  BodyShape shape = BodyShape::sphere;
  BodyMotion motion = BodyMotion::floating;
  double radius = 1.0;
  double mass = 1.0;                      // floating only: mass = density * water_density * volume
  double density = 0.0;                   // floating only, relative to water (0: from the mass)
  std::array<double, 3> position{};       // floating: at step 0
  std::array<double, 3> velocity{};       // floating: at step 0
  std::vector<PathKey> path;              // kinematic: steps strictly increasing, held after the last
  bool operator==(const BodySpec&) const = default;
};

struct WaterSpec {
  GridSpec grid;
  Physics physics;
  BasinSpec basin;
  NodeKind border = NodeKind::fixed;
  std::vector<ConstraintRect> constraints;
  std::vector<Perturbation> perturbations;
  std::vector<BodySpec> bodies;
  bool operator==(const WaterSpec&) const = default;
};

}  // namespace pond::sim
