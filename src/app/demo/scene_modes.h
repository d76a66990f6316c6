#pragma once
// The demo's constraint modes of the paper, applied to the scene it was started with: the border
// kind (fixed / vertical / free), every node vertical-only (waves pass through each other), and
// islands on or off (the scene's fixed rectangles; a scene without any gets one island in the
// middle of the pond when they are switched on).
#include "scene/scene.h"

namespace pond::app::demo {

struct SceneModes {
  sim::NodeKind border = sim::NodeKind::fixed;
  bool all_vertical = false;
  bool islands = true;
};

SceneModes modes_of(const scene::Scene& scene);                       // what the scene itself says
scene::Scene apply_modes(const scene::Scene& base, const SceneModes& modes);
const char* border_name(sim::NodeKind kind);
sim::NodeKind next_border(sim::NodeKind kind);  // fixed -> vertical -> free -> fixed

}  // namespace pond::app::demo
