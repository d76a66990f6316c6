#pragma once
// A scene as a simulation session takes it: its water, wind, tree count and sun, with the scene
// file's own checks as the rules run-time edits must pass (the demo's physics and added bodies).
#include "scene/scene.h"
#include "sim/session.h"

namespace pond::scene {

sim::SessionSpec session_spec(const Scene& scene);

}  // namespace pond::scene
