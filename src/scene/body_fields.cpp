#include "scene/body_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace pond::scene {
namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// A world position [x, y, z] must lie over the grid: x in [0, (cols-1) h], z in [0, (rows-1) h].
std::optional<std::string> off_grid(const std::array<double, 3>& p, const sim::GridSpec& g) {
  const double max_x = (g.cols - 1) * g.spacing, max_z = (g.rows - 1) * g.spacing;
  if (p[0] >= 0.0 && p[0] <= max_x && p[2] >= 0.0 && p[2] <= max_z) return std::nullopt;
  return "is outside the grid: x must be in [0, " + number_text(max_x) + "] and z in [0, " + number_text(max_z) + "]";
}

// "path": [[step, x, y, z], ...], steps integers >= 0 in increasing order.
std::vector<sim::PathKey> parse_path(JsonFields& f) {
  if (!f.has("path")) f.fail("path", "is missing (a kinematic body follows a path of [step, x, y, z] keys)");
  const auto& keys = f.array("path");
  if (keys.empty()) f.fail("path", "is empty");
  std::vector<sim::PathKey> path;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const std::string key = "path[" + std::to_string(k) + "]";
    const auto& v = keys[k];
    if (!v.is_array() || v.size() != 4 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number() ||
        !v[3].is_number())
      f.fail(key.c_str(), "must be a key [step, x, y, z] of four numbers");
    const double step = v[0].get<double>();
    if (!(step >= 0.0 && step <= 1e15 && std::floor(step) == step))
      f.fail(key.c_str(), "has step " + number_text(step) + ": a step must be an integer >= 0");
    sim::PathKey p{static_cast<std::int64_t>(step), {v[1].get<double>(), v[2].get<double>(), v[3].get<double>()}};
    for (double c : p.position)
      if (!std::isfinite(c)) f.fail(key.c_str(), "must be finite");
    if (!path.empty() && p.step <= path.back().step)
      f.fail(key.c_str(), "has step " + std::to_string(p.step) + ", not after the key before it (step " +
                              std::to_string(path.back().step) + "): steps must increase");
    path.push_back(p);
  }
  return path;
}

}  // namespace

sim::BodySpec parse_body(JsonFields f, const sim::GridSpec& g) {
  sim::BodySpec b;
  f.text("shape", "sphere", {"sphere"});
  if (!f.has("motion")) f.fail("motion", "is missing (kinematic | floating)");
  b.motion = f.text("motion", "floating", {"kinematic", "floating"}) == "kinematic" ? sim::BodyMotion::kinematic
                                                                                    : sim::BodyMotion::floating;
  if (!f.has("radius")) f.fail("radius", "is missing");
  b.radius = f.number("radius", b.radius);
  if (b.motion == sim::BodyMotion::floating) {
    if (f.has("path")) f.fail("path", "is for kinematic bodies (this one is floating)");
    if (!f.has("mass")) f.fail("mass", "is missing (a floating body needs one)");
    b.mass = f.number("mass", b.mass);
    if (!f.has("position")) f.fail("position", "is missing");
    b.position = f.vec3("position", b.position);
    b.velocity = f.vec3("velocity", b.velocity);
  } else {
    for (const char* key : {"mass", "position", "velocity"})
      if (f.has(key)) f.fail(key, "is for floating bodies (this one is kinematic and follows its path)");
    b.path = parse_path(f);
  }
  if (const std::optional<Problem> problem = body_problem(b, g)) f.fail(problem->key.c_str(), problem->what);
  f.finish();
  return b;
}

std::optional<Problem> body_problem(const sim::BodySpec& b, const sim::GridSpec& g) {
  if (!(b.radius > 0.0)) return Problem{"radius", "must be positive"};
  if (!(b.radius >= g.spacing))
    return Problem{"radius", "is " + number_text(b.radius) + ", less than the grid spacing " + number_text(g.spacing) +
                                 ": a smaller sphere slips between the nodes"};
  if (!(b.radius <= 0.25 * std::max(g.rows, g.cols) * g.spacing))
    return Problem{"radius", "is " + number_text(b.radius) + ", more than a quarter of the grid's extent"};
  if (b.motion == sim::BodyMotion::floating) {
    if (!(b.mass > 0.0 && std::isfinite(b.mass))) return Problem{"mass", "must be positive"};
    if (const std::optional<std::string> what = off_grid(b.position, g)) return Problem{"position", *what};
  }
  if (b.motion == sim::BodyMotion::kinematic && b.path.empty()) return Problem{"path", "is empty"};
  for (std::size_t k = 0; k < b.path.size(); ++k)
    if (const std::optional<std::string> what = off_grid(b.path[k].position, g))
      return Problem{"path[" + std::to_string(k) + "]", *what};
  return std::nullopt;
}

}  // namespace pond::scene
