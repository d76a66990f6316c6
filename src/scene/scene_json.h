#pragma once
// A scene written back as the scene file's JSON (docs/scenes.md): every key the parser reads, with
// doubles in their shortest text that reads back to the same bits, so parse_scene() of it gives
// the same Scene (checkpoints carry their scene this way, edits included).
#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"

namespace pond::scene {

nlohmann::json scene_to_json(const Scene& scene);
std::string scene_json(const Scene& scene);  // scene_to_json(), indented

}  // namespace pond::scene
