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
  spec.rules.physics = check_physics;
  spec.rules.body = [](const sim::BodySpec& body, const sim::GridSpec& grid, std::size_t index) {
    if (index >= kMaxBodies) throw InputError("a scene holds at most " + std::to_string(kMaxBodies) + " bodies");
    if (const std::optional<Problem> p = body_problem(body, grid))
      throw InputError("bodies[" + std::to_string(index) + "]." + p->key + " " + p->what);
  };
  return spec;
}

}  // namespace pond::scene
