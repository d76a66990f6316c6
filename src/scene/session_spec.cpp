#include "scene/session_spec.h"

#include <string>

#include "core/errors.h"
#include "scene/body_fields.h"

namespace pond::scene {

sim::SessionSpec session_spec(const Scene& scene) {
  sim::SessionSpec spec;
  spec.water = scene;
  spec.wind = scene.wind;
  spec.trees = scene.tree ? scene.tree->positions.size() : 0;
  spec.sun = scene.lighting.sun;
  spec.rules.physics = [](const sim::Physics& physics, const sim::WaterSpec& water) {
    check_physics(physics);
    sim::WaterSpec edited = water;
    edited.physics = physics;
    const std::vector<std::uint8_t> kinds = sim::node_kinds(water);
    for (std::size_t b = 0; b < water.bodies.size(); ++b)
      if (water.bodies[b].motion == sim::BodyMotion::floating)
        if (const std::optional<Problem> p = body_problem(water.bodies[b], edited, kinds);
            p && (p->key == "density" || p->key == "mass"))
          throw InputError("physics: bodies[" + std::to_string(b) + "]." + p->key + " " + p->what);
  };
  spec.rules.body = [](const sim::BodySpec& body, const sim::WaterSpec& water, const std::vector<std::uint8_t>& kinds,
                       const std::vector<std::array<double, 3>>& positions) {
    const std::size_t index = water.bodies.size();
    const std::string key = "bodies[" + std::to_string(index) + "].";
    if (index >= kMaxBodies) throw InputError("a scene holds at most " + std::to_string(kMaxBodies) + " bodies");
    if (const std::optional<Problem> p = body_problem(body, water, kinds)) throw InputError(key + p->key + " " + p->what);
    std::vector<sim::BodySpec> bodies = water.bodies;
    std::vector<std::array<double, 3>> at = positions;
    bodies.push_back(body);
    at.push_back(start_position(body));
    if (const std::optional<Overlap> o = first_overlap(bodies, at); o && o->index + 1 == bodies.size())
      throw InputError(key + (body.motion == sim::BodyMotion::floating ? "position " : "path[0] ") + o->what);
  };
  return spec;
}

}  // namespace pond::scene
