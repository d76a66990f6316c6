#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unistd.h>

#include "core/errors.h"
#include "core/output_file.h"
#include "core/text.h"
#include "scene/body_fields.h"
#include "scene/json_fields.h"
#include "scene/number_limits.h"
#include "sim/model.h"
#include "sim/stability.h"

namespace pond::scene {

using sim::ConstraintRect;
using sim::GridSpec;
using sim::NodeKind;
using sim::Perturbation;
using sim::PerturbMode;
using sim::PerturbTarget;
using sim::Physics;
using tree::TreeBend;
using tree::TreeDraw;
using tree::TreeSpec;
using tree::WindSpec;
using view::CameraSpec;
using view::LightingSpec;
using view::ViewSpec;
namespace {

#include "default_scene.inc"  // kDefaultSceneJson, generated from scenes/default.json

// Bytes the CPU solver holds per node: two states of 6 floats, normals, the kind byte.
constexpr double kBytesPerNode = 2 * 6 * 4 + 3 * 4 + 1;
constexpr int kMaxGridSide = 1 << 16;
constexpr int kMaxSubsteps = 10000;
constexpr std::size_t kMaxTrees = 64;  // instances of the scene's tree

NodeKind parse_kind(JsonFields& f, const char* key, bool allow_free) {
  const std::string s = allow_free ? f.text(key, "fixed", {"fixed", "vertical", "free"})
                                   : f.text(key, "fixed", {"fixed", "vertical"});
  if (s == "vertical") return NodeKind::vertical;
  if (s == "free") return NodeKind::free;
  return NodeKind::fixed;
}

// A length (world units) that must lie within [lo, hi] grid spacings (scene/number_limits.h).
void check_spacings(JsonFields& f, const char* key, double length, const GridSpec& g, double lo = kMinLengthSpacings,
                    double hi = kMaxSpacings) {
  if (outside(std::fabs(length) / g.spacing, lo, hi))
    f.fail(key, "is " + number_text(length) + " (" + number_outside(std::fabs(length) / g.spacing, lo, hi) +
                    " grid spacings), outside [" + number_text(lo) + ", " + number_text(hi) + "] spacings");
}

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 1e18;
}

void parse_grid(JsonFields f, GridSpec& g) {
  g.rows = static_cast<int>(f.integer("rows", g.rows, 2, kMaxGridSide));
  g.cols = static_cast<int>(f.integer("cols", g.cols, 2, kMaxGridSide));
  g.spacing = f.number("spacing", g.spacing);
  if (!(g.spacing > 0.0)) f.fail("spacing", "must be positive");
  if (std::optional<std::string> what = outside(g.spacing, kMinScale, kMaxScale)) f.fail("spacing", *what);
  f.finish();
  const double bytes = static_cast<double>(g.rows) * g.cols * kBytesPerNode;
  if (bytes > 0.75 * physical_memory_bytes())
    f.fail("is " + std::to_string(g.rows) + " x " + std::to_string(g.cols) + ": needs " +
           std::to_string(static_cast<long long>(bytes / (1 << 20))) +
           " MiB, more than this machine's memory allows");
}

void parse_physics(JsonFields f, Physics& p) {
  p.mass = f.number("mass", p.mass);
  p.stiffness = f.number("stiffness", p.stiffness);
  p.damping = f.number("damping", p.damping);
  p.dt = f.number("dt", p.dt);
  p.substeps = static_cast<int>(f.integer("substeps", p.substeps, 1, kMaxSubsteps));
  p.rest_ratio = f.number("rest_ratio", p.rest_ratio);
  p.gravity = f.number("gravity", p.gravity);
  p.water_density = f.number("water_density", p.water_density);
  p.body_drag = f.number("body_drag", p.body_drag);
  if (const std::optional<Problem> problem = physics_problem(p)) f.fail(problem->key.c_str(), problem->what);
  f.finish();
}

ConstraintRect parse_constraint(JsonFields f, const GridSpec& g) {
  ConstraintRect c;
  if (!f.has("kind")) f.fail("kind", "is missing");
  c.kind = parse_kind(f, "kind", false);
  f.index_range("rows", g.rows - 1, c.row0, c.row1);
  f.index_range("cols", g.cols - 1, c.col0, c.col1);
  f.finish();
  return c;
}

Perturbation parse_perturbation(JsonFields f, const GridSpec& g, const Physics& physics) {
  Perturbation p;
  for (const char* key : {"row", "col", "radius", "amplitude"})
    if (!f.has(key)) f.fail(key, "is missing");
  p.step = f.integer("step", 0, 0, INT64_MAX / 2);
  p.row = f.number("row", 0);
  if (p.row < 0 || p.row > g.rows - 1)
    f.fail("row", "is outside the grid's rows [0, " + std::to_string(g.rows - 1) + "]");
  p.col = f.number("col", 0);
  if (p.col < 0 || p.col > g.cols - 1)
    f.fail("col", "is outside the grid's columns [0, " + std::to_string(g.cols - 1) + "]");
  p.radius = f.number("radius", p.radius);
  if (!(p.radius > 0.0)) f.fail("radius", "must be positive");
  check_spacings(f, "radius", p.radius, g);
  p.amplitude = f.number("amplitude", p.amplitude);
  p.target = f.text("target", "velocity", {"velocity", "position"}) == "position"
                 ? PerturbTarget::position : PerturbTarget::velocity;
  // A position in spacings; a velocity in the spacings it moves a node a step.
  const bool position = p.target == PerturbTarget::position;
  const double spacings = std::fabs(p.amplitude) * (position ? 1.0 : physics.dt) / g.spacing;
  if (outside(spacings, 0.0, kMaxSpacings))
    f.fail("amplitude", "is " + number_text(p.amplitude) + " (" + number_outside(spacings, 0.0, kMaxSpacings) +
                            (position ? " grid spacings" : " grid spacings a step") + "), outside [0, " +
                            number_text(kMaxSpacings) + "]");
  p.mode = f.text("mode", "add", {"add", "set"}) == "set" ? PerturbMode::set : PerturbMode::add;
  f.finish();
  return p;
}

std::array<double, 3> color(JsonFields& f, const char* key, std::array<double, 3> fallback) {
  const std::array<double, 3> c = f.vec3(key, fallback);
  for (double d : c)
    if (d < 0.0 || d > 1.0) f.fail(key, "must be an RGB colour with components in [0, 1]");
  return c;
}

CameraSpec parse_camera(JsonFields f) {
  CameraSpec c;
  for (const char* key : {"eye", "target"})
    if (!f.has(key)) f.fail(key, "is missing");
  c.eye = f.vec3("eye", c.eye);
  c.target = f.vec3("target", c.target);
  for (const auto& [key, point] : {std::pair{"eye", c.eye}, std::pair{"target", c.target}})
    for (double x : point)
      if (std::optional<std::string> what = outside(x, -view::kMaxCameraCoordinate, view::kMaxCameraCoordinate))
        f.fail(key, "has a coordinate that " + *what + " (float view matrices)");
  if (c.eye == c.target) f.fail("target", "must differ from camera.eye");
  c.fovy_degrees = f.number("fovy", c.fovy_degrees);
  if (!(c.fovy_degrees >= view::kMinFovyDegrees && c.fovy_degrees <= view::kMaxFovyDegrees))
    f.fail("fovy", "must be in [" + number_text(view::kMinFovyDegrees) + ", " + number_text(view::kMaxFovyDegrees) + "] degrees");
  f.finish();
  return c;
}

// "basin": the floor and the land (sim::BasinSpec). Its keys were "view.floor_depth" and
// "view.land_height", which still work (parse_view) but not beside the new ones. Returns how many
// of the two keys it gave (bit 0: floor_depth, bit 1: land_height).
constexpr const char* kBasinKeys[2] = {"floor_depth", "land_height"};

double& basin_value(sim::BasinSpec& b, int k) { return k == 0 ? b.floor_depth : b.land_height; }

int parse_basin(JsonFields f, sim::BasinSpec& b, const GridSpec& g) {
  int given = 0;
  for (int k = 0; k < 2; ++k) {
    if (!f.has(kBasinKeys[k])) continue;
    basin_value(b, k) = f.number(kBasinKeys[k], basin_value(b, k));
    if (!(basin_value(b, k) > 0.0)) f.fail(kBasinKeys[k], "must be positive");
    check_spacings(f, kBasinKeys[k], basin_value(b, k), g);
    given |= 1 << k;
  }
  f.finish();
  return given;
}

void parse_view(JsonFields f, ViewSpec& v, sim::BasinSpec& basin, int basin_given, const GridSpec& g) {
  v.steps_per_frame = f.integer("steps_per_frame", v.steps_per_frame, 0, 1000000);
  v.lod_tolerance_px = f.number("lod_tolerance", v.lod_tolerance_px);
  if (v.lod_tolerance_px < 0.0) f.fail("lod_tolerance", "must not be negative (0 = the full mesh)");
  if (std::optional<std::string> what = outside(v.lod_tolerance_px, 0.0, kMaxScale, " pixels"))
    f.fail("lod_tolerance", *what);
  for (int k = 0; k < 2; ++k) {
    const char* key = kBasinKeys[k];
    if (!f.has(key)) continue;
    if (basin_given & (1 << k))
      f.fail(key, std::string("is given twice: it is basin.") + key + " now; remove view." + key);
    basin_value(basin, k) = f.number(key, basin_value(basin, k));
    if (!(basin_value(basin, k) > 0.0)) f.fail(key, std::string("must be positive (it is basin.") + key + " now)");
    check_spacings(f, key, basin_value(basin, k), g);
  }
  for (const view::EffectEntry& e : view::kEffects) v.effects.*e.flag = f.boolean(e.key, v.effects.*e.flag);
  f.finish();
}

void parse_lighting(JsonFields f, LightingSpec& l) {
  l.sun = f.vec3("sun", l.sun);
  if (const std::optional<Problem> problem = sun_problem(l.sun)) f.fail(problem->key.c_str(), problem->what);
  l.sun = sun_direction(l.sun);
  l.water = color(f, "water", l.water);
  l.absorption = f.vec3("absorption", l.absorption);
  for (double a : l.absorption)
    if (!(a >= 0.0 && a <= 100.0)) f.fail("absorption", "must be three coefficients per world unit in [0, 100]");
  l.sky = color(f, "sky", l.sky);
  l.ground = color(f, "ground", l.ground);
  f.finish();
}

// "tree": see TreeSpec. Positions must lie on the grid; absent, the tree stands on the island.
TreeSpec parse_tree(JsonFields f, const Scene& scene) {
  TreeSpec t;
  t.depth = static_cast<int>(f.integer("depth", t.depth, 1, 10));
  t.seed = static_cast<std::uint64_t>(f.integer("seed", static_cast<std::int64_t>(t.seed), 0, INT64_MAX));
  t.height = f.number("height", t.height);
  if (!(t.height > 0.0)) f.fail("height", "must be positive");
  check_spacings(f, "height", t.height, scene.grid);
  const auto& ps = f.array("positions");
  if (ps.size() > kMaxTrees) f.fail("positions", "holds more than " + std::to_string(kMaxTrees) + " trees");
  const GridSpec& g = scene.grid;
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const std::string key = "positions[" + std::to_string(k) + "]";
    const auto& p = ps[k];
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      f.fail(key.c_str(), "must be a grid position [row, col] of two numbers");
    const double row = p[0].get<double>(), col = p[1].get<double>();
    if (!(row >= 0 && row <= g.rows - 1 && col >= 0 && col <= g.cols - 1))
      f.fail(key.c_str(), "is outside the grid [0, " + std::to_string(g.rows - 1) + "] x [0, " +
                              std::to_string(g.cols - 1) + "]");
    t.positions.push_back({row, col});
  }
  if (ps.empty()) {
    const ConstraintRect* island = nullptr;
    for (const ConstraintRect& c : scene.constraints)
      if (c.kind == NodeKind::fixed && !island) island = &c;
    if (!island) f.fail("positions", "is missing and the scene has no fixed constraint (island) to stand on");
    t.positions.push_back({0.5 * (island->row0 + island->row1), 0.5 * (island->col0 + island->col1)});
  }
  t.bend = f.text("bend", "article", {"article", "keep-length"}) == "keep-length" ? TreeBend::keep_length
                                                                                   : TreeBend::article;
  t.draw = f.text("draw", "tubes", {"lines", "tubes"}) == "lines" ? TreeDraw::lines : TreeDraw::tubes;
  t.leaves = f.boolean("leaves", t.leaves);
  f.finish();
  return t;
}

void parse_wind(JsonFields f, WindSpec& w) {
  w.strength = f.number("strength", w.strength);
  if (!(w.strength >= 0.0 && w.strength <= 9.0)) f.fail("strength", "must be in [0, 9]");
  w.direction_deg = f.number("direction_deg", w.direction_deg);
  if (std::optional<std::string> what = outside(w.direction_deg, -kMaxDegrees, kMaxDegrees, " degrees"))
    f.fail("direction_deg", *what);
  w.seed = static_cast<std::uint64_t>(f.integer("seed", static_cast<std::int64_t>(w.seed), 0, INT64_MAX));
  w.ripples = f.boolean("ripples", w.ripples);
  f.finish();
}

// "bodies": each checked against the water (body_problem), then against each other.
void parse_bodies(JsonFields& f, Scene& s, const std::string& source, bool check_overlaps) {
  const auto& bs = f.array("bodies");
  if (bs.size() > kMaxBodies) f.fail("bodies", "holds more than " + std::to_string(kMaxBodies) + " bodies");
  if (bs.empty()) return;
  const std::vector<std::uint8_t> kinds = sim::node_kinds(s);
  std::vector<std::array<double, 3>> starts;
  for (std::size_t i = 0; i < bs.size(); ++i) {
    JsonFields body(bs[i], "bodies[" + std::to_string(i) + "]", source);
    s.bodies.push_back(parse_body(body));
    if (const std::optional<Problem> p = body_problem(s.bodies.back(), s, kinds)) body.fail(p->key.c_str(), p->what);
    starts.push_back(start_position(s.bodies.back()));
  }
  if (!check_overlaps) return;
  if (const std::optional<Overlap> o = first_overlap(s.bodies, starts)) {
    const bool floating = s.bodies[o->index].motion == sim::BodyMotion::floating;
    JsonFields(bs[o->index], "bodies[" + std::to_string(o->index) + "]", source)
        .fail(floating ? "position" : "path[0]", o->what);
  }
}

}  // namespace

std::optional<Problem> physics_problem(const Physics& p) {
  if (!(p.mass > 0.0)) return Problem{"mass", "must be positive"};
  if (!(p.stiffness >= 0.0)) return Problem{"stiffness", "must not be negative"};
  if (!(p.damping >= 0.0)) return Problem{"damping", "must not be negative"};
  if (!(p.dt > 0.0)) return Problem{"dt", "must be positive"};
  if (!(p.substeps >= 1 && p.substeps <= kMaxSubsteps))
    return Problem{"substeps", "must be in [1, " + std::to_string(kMaxSubsteps) + "]"};
  if (!(p.rest_ratio > 0.0)) return Problem{"rest_ratio", "must be positive"};
  if (!(p.gravity >= 0.0 && std::isfinite(p.gravity))) return Problem{"gravity", "must be finite and not negative"};
  if (!(p.water_density > 0.0 && std::isfinite(p.water_density))) return Problem{"water_density", "must be positive"};
  if (!(p.body_drag >= 0.0 && std::isfinite(p.body_drag)))
    return Problem{"body_drag", "must be finite and not negative"};
  // Each within the scale the solver's float constants are made of (scene/number_limits.h).
  const std::pair<const char*, double> scaled[] = {{"mass", p.mass}, {"dt", p.dt}, {"rest_ratio", p.rest_ratio},
                                                   {"water_density", p.water_density}};
  for (const auto& [key, value] : scaled)
    if (std::optional<std::string> what = outside(value, kMinScale, kMaxScale)) return Problem{key, *what};
  const std::pair<const char*, double> zero_or_scaled[] = {
      {"stiffness", p.stiffness}, {"damping", p.damping}, {"gravity", p.gravity}, {"body_drag", p.body_drag}};
  for (const auto& [key, value] : zero_or_scaled)
    if (std::optional<std::string> what = outside(value, 0.0, kMaxScale)) return Problem{key, *what};
  const double bound = sim::stability_bound(p.mass, p.stiffness, p.damping);
  const double sub_dt = p.dt / p.substeps;
  if (!(sub_dt < bound)) {
    // In double: a tiny bound (a huge damping) needs more substeps than an int holds.
    const double needed = std::floor(p.dt / bound) + 1.0;
    char msg[256];
    std::snprintf(msg, sizeof msg,
                  "%g%s exceeds the semi-implicit Euler stability bound %.6g for mass %g, "
                  "stiffness %g, damping %g; use dt < %.6g or physics.substeps >= %.15g",
                  p.dt, p.substeps > 1 ? (" / " + std::to_string(p.substeps) + " substeps").c_str() : "",
                  bound, p.mass, p.stiffness, p.damping, bound, needed);
    return Problem{"dt", msg};
  }
  return std::nullopt;
}

std::optional<Problem> sun_problem(const std::array<double, 3>& s) {
  for (double d : s)
    if (!std::isfinite(d)) return Problem{"sun", "must be finite"};
  if (s[0] == 0.0 && s[1] == 0.0 && s[2] == 0.0) return Problem{"sun", "must not be zero"};
  return std::nullopt;
}

std::array<double, 3> sun_direction(const std::array<double, 3>& s) {
  const double largest = std::max({std::fabs(s[0]), std::fabs(s[1]), std::fabs(s[2])});
  if (largest >= 0x1p-500 && largest <= 0x1p500) return s;  // its squares are normal doubles
  int exponent = 0;
  std::frexp(largest, &exponent);
  return {std::ldexp(s[0], -exponent), std::ldexp(s[1], -exponent), std::ldexp(s[2], -exponent)};
}

void check_physics(const Physics& physics) {
  if (const std::optional<Problem> p = physics_problem(physics)) throw InputError("physics." + p->key + " " + p->what);
}

void check_sun(const std::array<double, 3>& toward_sun) {
  if (const std::optional<Problem> p = sun_problem(toward_sun)) throw InputError("lighting." + p->key + " " + p->what);
}

std::string_view default_scene_json() { return kDefaultSceneJson; }

Scene parse_scene(std::string_view json_text, const std::string& file, ParseOptions options) {
  const std::string source = escaped(file);  // as messages show it
  const nlohmann::json root = parse_json(json_text, source);
  JsonFields f(root, "", source);
  Scene s;
  s.name = f.text("name", "", {});
  parse_grid(JsonFields(f.object("grid"), "grid", source), s.grid);
  parse_physics(JsonFields(f.object("physics"), "physics", source), s.physics);
  s.border = parse_kind(f, "border", true);
  const auto& cs = f.array("constraints");
  for (std::size_t i = 0; i < cs.size(); ++i)
    s.constraints.push_back(parse_constraint(
        JsonFields(cs[i], "constraints[" + std::to_string(i) + "]", source), s.grid));
  const auto& ps = f.array("perturbations");
  for (std::size_t i = 0; i < ps.size(); ++i)
    s.perturbations.push_back(parse_perturbation(
        JsonFields(ps[i], "perturbations[" + std::to_string(i) + "]", source), s.grid, s.physics));
  const int basin_given = parse_basin(JsonFields(f.object("basin"), "basin", source), s.basin, s.grid);
  parse_view(JsonFields(f.object("view"), "view", source), s.view, s.basin, basin_given, s.grid);
  parse_bodies(f, s, source, options.body_overlaps);
  if (f.has("camera")) s.camera = parse_camera(JsonFields(f.object("camera"), "camera", source));
  parse_lighting(JsonFields(f.object("lighting"), "lighting", source), s.lighting);
  if (f.has("tree")) s.tree = parse_tree(JsonFields(f.object("tree"), "tree", source), s);
  parse_wind(JsonFields(f.object("wind"), "wind", source), s.wind);
  f.finish();
  return s;
}

Scene load_scene(const std::string& path) {
  if (path.empty()) return parse_scene(default_scene_json(), "default scene");
  return parse_scene(read_file(path), path);
}

}  // namespace pond::scene
