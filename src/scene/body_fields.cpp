#include "scene/body_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "sim/basin.h"
#include "core/text.h"
#include "scene/number_limits.h"
#include "sim/bodies.h"

namespace pond::scene {
namespace {

// Densities above this are refused: denser than any metal.
constexpr double kMaxDensity = 100.0;
constexpr double kMinDensity = 0.01;


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

double length(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

std::optional<Problem> size_problem(const sim::BodySpec& b, const sim::WaterSpec& w) {
  const sim::GridSpec& g = w.grid;
  if (!(b.radius > 0.0)) return Problem{"radius", "must be positive"};
  if (!(b.radius >= g.spacing))
    return Problem{"radius", "is " + number_text(b.radius) + ", less than the grid spacing " + number_text(g.spacing) +
                                 ": a smaller sphere slips between the nodes"};
  const double interior = std::min(g.rows - 1, g.cols - 1) * g.spacing;
  if (!(2.0 * b.radius <= interior))
    return Problem{"radius", "is " + number_text(b.radius) + ": the sphere is wider than the pond's interior (" +
                                 number_text(interior) + ")"};
  if (b.motion == sim::BodyMotion::floating && !(b.radius <= w.basin.floor_depth))
    return Problem{"radius", "is " + number_text(b.radius) + ", more than the pool is deep (basin.floor_depth " +
                                 number_text(w.basin.floor_depth) + "): a floating ball could not float free"};
  return std::nullopt;
}

std::optional<Problem> density_problem(const sim::BodySpec& b, const sim::Physics& p) {
  const char* key = b.density > 0.0 ? "density" : "mass";
  if (b.density <= 0.0 && !(b.mass > 0.0 && std::isfinite(b.mass))) return Problem{"mass", "must be positive"};
  const double density = sim::body_density(b, p);
  const DensityRange range = stable_densities(b.radius, p);
  if (density >= range.min && density <= range.max) return std::nullopt;
  const std::string shown = number_outside(density, range.min, range.max);
  std::string what = "gives a density of " + shown + " (relative to water);";
  if (b.density > 0.0) what = "is " + shown + ";";
  const double volume = sim::sphere_volume(b.radius) * p.water_density;
  return Problem{key, what + " a floating ball of radius " + number_text(b.radius) + " is stable for densities in [" +
                          number_text(range.min) + ", " + number_text(range.max) + "] (masses [" +
                          number_text(range.min * volume) + ", " + number_text(range.max * volume) + "])"};
}

std::optional<Problem> motion_problem(const sim::BodySpec& b, const sim::WaterSpec& w,
                                      const std::vector<std::uint8_t>& kinds) {
  const double h = w.grid.spacing, fastest = POND_MAX_SPACINGS_PER_STEP * h / w.physics.dt;  // world / time
  if (b.motion == sim::BodyMotion::kinematic) {
    if (b.path.empty()) return Problem{"path", "is empty"};
    for (std::size_t k = 0; k < b.path.size(); ++k) {
      const std::string key = "path[" + std::to_string(k) + "]";
      if (const std::optional<std::string> what = off_grid(b.path[k].position, w.grid)) return Problem{key, *what};
      if (const double y = b.path[k].position[1] / h; outside(y, -kMaxSpacings, kMaxSpacings))
        return Problem{key, "has y " + number_text(b.path[k].position[1]) + " (" + number_outside(y, -kMaxSpacings, kMaxSpacings) +
                                " grid spacings), outside [-" + number_text(kMaxSpacings) + ", " + number_text(kMaxSpacings) + "]"};
      if (k == 0) continue;
      const auto &a = b.path[k - 1].position, &c = b.path[k].position;
      const double per_step = length({c[0] - a[0], c[1] - a[1], c[2] - a[2]}) /
                              static_cast<double>(b.path[k].step - b.path[k - 1].step) / h;
      if (per_step > POND_MAX_SPACINGS_PER_STEP)
        return Problem{key, "moves the body " + number_text(per_step) + " spacings a step; at most " +
                                number_text(POND_MAX_SPACINGS_PER_STEP)};
    }
    return std::nullopt;
  }
  if (const std::optional<std::string> what = off_grid(b.position, w.grid)) return Problem{"position", *what};
  if (const std::optional<std::string> solid = sim::sphere_in_solid(kinds, w.grid, w.basin, b.position, b.radius))
    return Problem{"position", "puts the ball into " + *solid};
  // Where a fall from rest reaches the fastest motion; at most a million spacings up (a tiny gravity).
  const double top = std::min(w.physics.gravity > 0.0 ? fastest * fastest / (2.0 * w.physics.gravity) : kMaxSpacings * h,
                              kMaxSpacings * h);
  if (b.position[1] > w.basin.land_height + top)
    return Problem{"position", "has y " + number_text(b.position[1]) +
                                   (top < kMaxSpacings * h ? ": from higher than " + number_text(w.basin.land_height + top) +
                                                                 " a fall passes " + number_text(POND_MAX_SPACINGS_PER_STEP) +
                                                                 " spacings a step"
                                                           : ": higher than " + number_text(w.basin.land_height + top) +
                                                                 ", a million grid spacings above the land")};
  if (length(b.velocity) > fastest)
    return Problem{"velocity", "is " + number_text(length(b.velocity) / h * w.physics.dt) +
                                   " spacings a step; at most " + number_text(POND_MAX_SPACINGS_PER_STEP)};
  return std::nullopt;
}

// The body's float constants as the solver gets them (shared::BodyConstants), each finite and at most
// kMaxBodyConstant: the ratios of the body's and a node's masses, its drag and buoyancy a substep.
std::optional<Problem> constants_problem(const sim::BodySpec& b, const sim::WaterSpec& w) {
  const shared::BodyConstants c = sim::build_bodies({b}, w.physics, w.grid.spacing).front().constants;
  const char* mass_key = b.density > 0.0 ? "density" : "mass";
  const struct {
    float value;
    const char* what;
  } constants[] = {{c.body_over_node, "a body-to-node mass ratio (with physics.mass, water_density)"},
                   {c.node_over_body, "a node-to-body mass ratio (with physics.mass, water_density)"},
                   {c.inv_mass, "an inverse mass (with physics.water_density)"},
                   {c.buoyancy_dt, "a buoyancy a substep (with physics.gravity)"},
                   {c.drag_dt, "a drag rate a substep (with physics.body_drag)"}};
  for (const auto& k : constants)
    if (!(std::fabs(k.value) <= kMaxBodyConstant))
      return Problem{mass_key, "gives " + std::string(k.what) + " of " + number_text(k.value) + ", more than " +
                                   number_text(kMaxBodyConstant)};
  return std::nullopt;
}

}  // namespace

DensityRange stable_densities(double radius, const sim::Physics& p) {
  // Buoyancy is a spring of stiffness (3/4) g / (density r) per unit mass at the waterline
  // (d f / d hs at hs = r); semi-implicit Euler needs omega dt < 2: keep omega dt <= 1.
  const double sub_dt = p.dt / p.substeps;
  return {std::max(kMinDensity, 0.75 * p.gravity * sub_dt * sub_dt / radius), kMaxDensity};
}

sim::BodySpec parse_body(JsonFields f) {
  sim::BodySpec b;
  f.text("shape", "sphere", {"sphere"});
  if (!f.has("motion")) f.fail("motion", "is missing (kinematic | floating)");
  b.motion = f.text("motion", "floating", {"kinematic", "floating"}) == "kinematic" ? sim::BodyMotion::kinematic
                                                                                    : sim::BodyMotion::floating;
  if (!f.has("radius")) f.fail("radius", "is missing");
  b.radius = f.number("radius", b.radius);
  if (b.motion == sim::BodyMotion::floating) {
    if (f.has("path")) f.fail("path", "is for kinematic bodies (this one is floating)");
    if (f.has("mass") == f.has("density"))
      f.fail(f.has("mass") ? "density" : "mass",
             f.has("mass") ? "and mass are both given: give exactly one (density = mass / (water_density * volume))"
                           : "is missing: a floating body gives its density (relative to water) or its mass");
    if (f.has("density")) {
      b.density = f.number("density", 0.0);
      if (!(b.density > 0.0)) f.fail("density", "must be positive");
    } else {
      b.mass = f.number("mass", b.mass);
    }
    if (!f.has("position")) f.fail("position", "is missing");
    b.position = f.vec3("position", b.position);
    b.velocity = f.vec3("velocity", b.velocity);
  } else {
    for (const char* key : {"mass", "density", "position", "velocity"})
      if (f.has(key)) f.fail(key, "is for floating bodies (this one is kinematic and follows its path)");
    b.path = parse_path(f);
  }
  f.finish();
  return b;
}

std::optional<Problem> body_problem(const sim::BodySpec& b, const sim::WaterSpec& w,
                                    const std::vector<std::uint8_t>& kinds) {
  if (std::optional<Problem> p = size_problem(b, w)) return p;
  if (b.motion == sim::BodyMotion::floating)
    if (std::optional<Problem> p = density_problem(b, w.physics)) return p;
  if (std::optional<Problem> p = motion_problem(b, w, kinds)) return p;
  return b.motion == sim::BodyMotion::floating ? constants_problem(b, w) : std::nullopt;
}

std::array<double, 3> start_position(const sim::BodySpec& b) {
  return b.motion == sim::BodyMotion::floating || b.path.empty() ? b.position : b.path.front().position;
}

std::optional<Overlap> first_overlap(const std::vector<sim::BodySpec>& bodies,
                                     const std::vector<std::array<double, 3>>& at) {
  for (std::size_t j = 0; j < bodies.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      if (bodies[i].motion == sim::BodyMotion::kinematic && bodies[j].motion == sim::BodyMotion::kinematic) continue;
      const double d = length({at[j][0] - at[i][0], at[j][1] - at[i][1], at[j][2] - at[i][2]});
      if (d < bodies[i].radius + bodies[j].radius)
        return Overlap{j, "overlaps bodies[" + std::to_string(i) + "] (centres " + number_text(d) + " apart, radii " +
                              number_text(bodies[i].radius) + " + " + number_text(bodies[j].radius) + ")"};
    }
  return std::nullopt;
}

}  // namespace pond::scene
