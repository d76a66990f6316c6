#include "scene/scene_json.h"

#include <nlohmann/json.hpp>

namespace pond::scene {
namespace {

using nlohmann::json;

const char* kind_name(sim::NodeKind k) {
  return k == sim::NodeKind::free ? "free" : k == sim::NodeKind::vertical ? "vertical" : "fixed";
}

json vec(const std::array<double, 3>& v) { return json::array({v[0], v[1], v[2]}); }

json constraint_json(const sim::ConstraintRect& c) {
  return {{"kind", kind_name(c.kind)}, {"rows", {c.row0, c.row1}}, {"cols", {c.col0, c.col1}}};
}

json perturbation_json(const sim::Perturbation& p) {
  return {{"step", p.step},
          {"row", p.row},
          {"col", p.col},
          {"radius", p.radius},
          {"amplitude", p.amplitude},
          {"target", p.target == sim::PerturbTarget::position ? "position" : "velocity"},
          {"mode", p.mode == sim::PerturbMode::set ? "set" : "add"}};
}

json body_json(const sim::BodySpec& b) {
  json j = {{"shape", "sphere"}, {"radius", b.radius}};
  if (b.motion == sim::BodyMotion::kinematic) {
    j["motion"] = "kinematic";
    json path = json::array();
    for (const sim::PathKey& k : b.path) path.push_back({k.step, k.position[0], k.position[1], k.position[2]});
    j["path"] = std::move(path);
    return j;
  }
  j["motion"] = "floating";
  if (b.density > 0.0) {
    j["density"] = b.density;
  } else {
    j["mass"] = b.mass;
  }
  j["position"] = vec(b.position);
  j["velocity"] = vec(b.velocity);
  return j;
}

json tree_json(const tree::TreeSpec& t) {
  json positions = json::array();
  for (const auto& p : t.positions) positions.push_back({p[0], p[1]});
  return {{"depth", t.depth},
          {"seed", t.seed},
          {"height", t.height},
          {"positions", std::move(positions)},
          {"bend", t.bend == tree::TreeBend::keep_length ? "keep-length" : "article"},
          {"draw", t.draw == tree::TreeDraw::lines ? "lines" : "tubes"},
          {"leaves", t.leaves}};
}

}  // namespace

std::string scene_json(const Scene& s) { return scene_to_json(s).dump(1); }

json scene_to_json(const Scene& s) {
  json j;
  j["name"] = s.name;
  j["grid"] = {{"rows", s.grid.rows}, {"cols", s.grid.cols}, {"spacing", s.grid.spacing}};
  const sim::Physics& p = s.physics;
  j["physics"] = {{"mass", p.mass},         {"stiffness", p.stiffness},         {"damping", p.damping},
                  {"dt", p.dt},             {"substeps", p.substeps},           {"rest_ratio", p.rest_ratio},
                  {"gravity", p.gravity},   {"water_density", p.water_density}, {"body_drag", p.body_drag}};
  j["border"] = kind_name(s.border);
  j["constraints"] = json::array();
  for (const sim::ConstraintRect& c : s.constraints) j["constraints"].push_back(constraint_json(c));
  j["perturbations"] = json::array();
  for (const sim::Perturbation& q : s.perturbations) j["perturbations"].push_back(perturbation_json(q));
  j["basin"] = {{"floor_depth", s.basin.floor_depth}, {"land_height", s.basin.land_height}};
  j["bodies"] = json::array();
  for (const sim::BodySpec& b : s.bodies) j["bodies"].push_back(body_json(b));
  const view::ViewSpec& v = s.view;
  j["view"] = {{"steps_per_frame", v.steps_per_frame}, {"lod_tolerance", v.lod_tolerance_px}};
  for (const view::EffectEntry& e : view::kEffects) j["view"][e.key] = v.effects.*e.flag;
  if (s.camera) j["camera"] = {{"eye", vec(s.camera->eye)}, {"target", vec(s.camera->target)}, {"fovy", s.camera->fovy_degrees}};
  const view::LightingSpec& l = s.lighting;
  j["lighting"] = {{"sun", vec(l.sun)},     {"water", vec(l.water)},   {"absorption", vec(l.absorption)},
                   {"sky", vec(l.sky)},     {"ground", vec(l.ground)}};
  if (s.tree) j["tree"] = tree_json(*s.tree);
  j["wind"] = {{"strength", s.wind.strength}, {"direction_deg", s.wind.direction_deg}, {"seed", s.wind.seed},
               {"ripples", s.wind.ripples}};
  return j;
}

}  // namespace pond::scene
