#pragma once
// The built-in cases of `pond check`: scenes chosen to cover what can make a device's bits differ
// from the CPU's (each a scene file's JSON, run from rest for `steps` steps).
#include <cstdint>
#include <span>

#include "scene/scene.h"

namespace pond::app {

struct CheckCase {
  const char* name;
  const char* json;     // empty: the embedded default scene (the paper's pond)
  std::int64_t steps;   // default length; `pond check --steps N` replaces it
  const char* covers;   // what it is there for, one phrase
};

std::span<const CheckCase> check_cases();
scene::Scene check_scene(const CheckCase& c);  // its scene, parsed

}  // namespace pond::app
