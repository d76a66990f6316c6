#pragma once
// A scene as the user writes it (world units), parsed from the JSON contract in README.md.
// Parsing checks types, unknown keys and ranges and names the key's path in its InputError.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pond::sim {

enum class NodeKind : std::uint8_t { free = 0, vertical = 1, fixed = 2 };
enum class PerturbTarget { velocity, position };
enum class PerturbMode { add, set };

struct GridSpec {
  int rows = 50;
  int cols = 50;
  double spacing = 1.0;  // h
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
};

struct ConstraintRect {
  NodeKind kind = NodeKind::fixed;  // fixed or vertical
  int row0 = 0, row1 = 0;           // inclusive
  int col0 = 0, col1 = 0;           // inclusive
};

struct Perturbation {
  std::int64_t step = 0;  // applied just before integration step number `step` (0-based)
  double row = 0, col = 0;
  double radius = 1.0;  // world units
  double amplitude = 1.0;
  PerturbTarget target = PerturbTarget::velocity;
  PerturbMode mode = PerturbMode::add;
};

// How the scene is looked at (pond render, the demo); optional keys, world units.
// "camera": {"eye": [x, y, z], "target": [x, y, z], "fovy": degrees}; absent = a view of the whole
// pond chosen from the grid size.
struct CameraSpec {
  std::array<double, 3> eye{0, 10, 0};
  std::array<double, 3> target{0, 0, 1};
  double fovy_degrees = 45.0;
};

// "view": what a rendered frame advances and how the pond around the water is shaped.
struct ViewSpec {
  std::int64_t steps_per_frame = 1;  // simulation steps per rendered frame
  double lod_tolerance_px = 1.0;     // LOD screen-space error bound; 0 = the full mesh
  double floor_depth = 3.0;          // the pool floor lies this far below the rest surface
  double land_height = 1.0;          // shore, islands and pool rim rise this far above it
};

// "lighting": the sun and the colours the water shader mixes (linear RGB in [0, 1]).
struct LightingSpec {
  std::array<double, 3> sun{-0.3, 0.38, -0.87};   // direction toward the sun (normalized on use)
  std::array<double, 3> water{0.015, 0.11, 0.13};  // deep water (what light through it tends to)
  std::array<double, 3> sky{0.28, 0.52, 0.9};      // sky at the zenith (the horizon is lighter)
  std::array<double, 3> ground{0.55, 0.47, 0.33};  // pool floor, shore and islands
};

// "tree": wind trees (SPEC section 2) standing on the land; absent = no tree. One skeleton, drawn
// once per position (instances), each instance swaying with its own phase.
enum class TreeBend { article, keep_length };  // the article's stretching bend | length-preserving
enum class TreeDraw { lines, tubes };          // the article's line look | lit, tapered tubes
struct TreeSpec {
  int depth = 8;                  // recursion levels 1..10 (3281 vertices at 8)
  std::uint64_t seed = 1;         // the skeleton's and the twig jitter's random streams
  double height = 6.0;            // world units from the base to the highest rest vertex
  // [row, col] grid indices (fractional allowed) of each instance's base; its foot is at
  // view.land_height. Default: the centre of the first fixed constraint (the island).
  std::vector<std::array<double, 2>> positions;
  TreeBend bend = TreeBend::article;
  TreeDraw draw = TreeDraw::tubes;
  bool leaves = true;             // small leaves at the thinnest twigs' tips
};

// "wind": the user wind W the trees bend in (the demo's keys 1-9 and right drag); meaningful
// without a tree too when it ripples the water.
struct WindSpec {
  double strength = 3.0;       // 0 (calm) .. 9 (gale)
  double direction_deg = 0.0;  // in the xz plane, from +x toward +z (world)
  std::uint64_t seed = 1;      // the gust noise table
  bool ripples = false;        // gusts also drop small deterministic ripples on the water
};

struct Scene {
  std::string name;
  GridSpec grid;
  Physics physics;
  NodeKind border = NodeKind::fixed;
  std::vector<ConstraintRect> constraints;
  std::vector<Perturbation> perturbations;
  std::optional<CameraSpec> camera;
  ViewSpec view;
  LightingSpec lighting;
  std::optional<TreeSpec> tree;
  WindSpec wind;
};

// Parses and validates; `source` names the file in messages. Throws InputError.
Scene parse_scene(std::string_view json_text, const std::string& source);
Scene load_scene(const std::string& path);  // "" = the embedded default scene
std::string_view default_scene_json();

}  // namespace pond::sim
