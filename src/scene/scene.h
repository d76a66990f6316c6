#pragma once
// A scene file (JSON, the contract in docs/scenes.md): parsed and validated here, and nowhere else.
// Parsing checks types, unknown keys and ranges and names the key's path in its InputError; the
// checks that edits made at run time must pass too (the demo's physics and sun) are the same
// functions the parser calls.
#include <optional>
#include <string>
#include <string_view>

#include "sim/water_spec.h"
#include "tree/tree_spec.h"
#include "view/view_spec.h"

namespace pond::scene {

// The water (sim::WaterSpec: grid, physics, border, constraints, perturbations) and how it is shown.
struct Scene : sim::WaterSpec {
  std::string name;
  std::optional<view::CameraSpec> camera;
  view::ViewSpec view;
  view::LightingSpec lighting;
  std::optional<tree::TreeSpec> tree;
  tree::WindSpec wind;
  bool operator==(const Scene&) const = default;
};

// Parses and validates; `source` names the file in messages. Throws InputError. A checkpoint's
// scene skips one check: its bodies' start positions may overlap, as bodies added in the demo may
// start where others started (each was checked against the bodies where they were then).
struct ParseOptions {
  bool body_overlaps = true;
};
Scene parse_scene(std::string_view json_text, const std::string& source, ParseOptions options = {});
Scene load_scene(const std::string& path);  // "" = the embedded default scene
std::string_view default_scene_json();

// What is wrong with a value: the key under its object ("dt") and the complaint.
struct Problem {
  std::string key;
  std::string what;
};
// The "physics" object's ranges and the integrator's stability bound (sim/stability.h).
std::optional<Problem> physics_problem(const sim::Physics& physics);
// lighting.sun: a direction, finite and not zero.
std::optional<Problem> sun_problem(const std::array<double, 3>& toward_sun);
// The same direction, normalizable in double: a vector whose squares would overflow or vanish is
// scaled by a power of two to a largest component in [0.5, 1) ([1e200, 1e200, 0] and
// [1e-200, 1e-200, 0] both become [0.5, 0.5, 0]); any other is returned as it is.
std::array<double, 3> sun_direction(const std::array<double, 3>& toward_sun);
// Throws InputError("physics.<key> <what>") / ("lighting.sun ...") for a run-time edit.
void check_physics(const sim::Physics& physics);
void check_sun(const std::array<double, 3>& toward_sun);

}  // namespace pond::scene
