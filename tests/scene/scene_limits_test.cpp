// Hostile scene files (issue 60), by class: a key given twice, and every number outside the range
// where the arithmetic it feeds stays finite and meaningful, refused with the key's path.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "scene/scene.h"

namespace pond::scene {
namespace {

// The InputError parsing `json` gives ("" and a test failure when it parses).
std::string refusal(const std::string& json) {
  try {
    parse_scene(json, "test.json");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << json;
  return "";
}

TEST(SceneLimits, AKeyGivenTwiceIsRefusedWithItsPath) {
  EXPECT_EQ(refusal(R"({"grid": {"rows": 10, "rows": 20}})"), "test.json: grid.rows is given twice");
  EXPECT_EQ(refusal(R"({"border": "fixed", "grid": {}, "border": "free"})"), "test.json: border is given twice");
  EXPECT_EQ(refusal(R"({"perturbations": [{"row": 1, "col": 1, "radius": 1, "amplitude": 1},
                                           {"row": 1, "col": 1, "radius": 1, "amplitude": 1, "radius": 2}]})"),
            "test.json: perturbations[1].radius is given twice");
  EXPECT_EQ(refusal(R"({"lighting": {"sun": [1, 1, 1]}, "tree": {"positions": [[1, 1], [2, 2]], "positions": []}})"),
            "test.json: tree.positions is given twice");
  // The same key in two objects, or in an object inside an array, is no repetition.
  EXPECT_NO_THROW(parse_scene(R"({"grid": {"rows": 10}, "basin": {"floor_depth": 2}, "view": {"reflections": true},
                                 "constraints": [{"kind": "fixed", "rows": [1, 2], "cols": [1, 2]},
                                                 {"kind": "fixed", "rows": [4, 5], "cols": [4, 5]}]})",
                              "ok.json"));
  // Many keys (the set behind the list): the repeat is still found.
  std::string many = R"({"name": "x", "view": {)";
  for (int k = 0; k < 40; ++k) many += "\"k" + std::to_string(k) + "\": 1, ";
  EXPECT_EQ(refusal(many + R"("k7": 2}})"), "test.json: view.k7 is given twice");
}

}  // namespace
}  // namespace pond::scene
