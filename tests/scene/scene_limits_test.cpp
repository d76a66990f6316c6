// Hostile scene files (issue 60), by class: a key given twice, and every number outside the range
// where the arithmetic it feeds stays finite and meaningful, refused with the key's path.
#include <gtest/gtest.h>

#include <array>
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

TEST(SceneLimits, ANumberBeyondADoubleIsRefusedWithItsPath) {
  const auto starts = [](const std::string& text, const std::string& head) { return text.rfind(head, 0) == 0; };
  EXPECT_TRUE(starts(refusal(R"({"physics": {"dt": 1e3080}})"), "test.json: physics.dt is a number beyond a double's range"));
  EXPECT_TRUE(starts(refusal(R"({"bodies": [{"motion": "floating", "position": [1, -1e999, 2]}]})"),
                     "test.json: bodies[0].position[1] is a number beyond"));
  EXPECT_TRUE(starts(refusal(R"({"grid": {"rows": 10}, "perturbations": [{"row": 1}, {"amplitude": 2e400}]})"),
                     "test.json: perturbations[1].amplitude is a number beyond"));
  EXPECT_TRUE(starts(refusal("1e999"), "test.json: the scene is a number beyond"));
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

// `json`'s refusal contains `text` (the key's path and the complaint).
::testing::AssertionResult refused(const std::string& json, const std::string& text) {
  const std::string m = refusal(json);
  if (m.find(text) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << m << "' does not contain '" << text << "'";
}

TEST(SceneLimits, PhysicsStaysWithinTheFloatConstantsScale) {
  EXPECT_TRUE(refused(R"({"physics": {"body_drag": 1e39}})", "physics.body_drag is 1e+39, outside [0, 1e+06]"));
  EXPECT_TRUE(refused(R"({"physics": {"water_density": 1e39}})", "physics.water_density is 1e+39, outside [1e-06, 1e+06]"));
  EXPECT_TRUE(refused(R"({"physics": {"water_density": 1e-300}})", "physics.water_density is 1e-300"));
  EXPECT_TRUE(refused(R"({"physics": {"mass": 1e-300}})", "physics.mass is 1e-300, outside"));
  EXPECT_TRUE(refused(R"({"physics": {"stiffness": 1e300}})", "physics.stiffness is 1e+300, outside"));
  EXPECT_TRUE(refused(R"({"physics": {"gravity": 1e7}})", "physics.gravity is 1e+07, outside"));
  EXPECT_TRUE(refused(R"({"physics": {"rest_ratio": 1e300}})", "physics.rest_ratio is 1e+300, outside"));
  EXPECT_NO_THROW(parse_scene(R"({"physics": {"body_drag": 1e6, "water_density": 1e-6, "gravity": 0, "stiffness": 0}})", "x"));
  // A demo edit is held to the same ranges.
  sim::Physics p;
  p.body_drag = 1e39;
  EXPECT_THROW(check_physics(p), InputError);
}

TEST(SceneLimits, LengthsStayWithinAMillionGridSpacings) {
  EXPECT_TRUE(refused(R"({"grid": {"spacing": 1e-300}})", "grid.spacing is 1e-300, outside [1e-06, 1e+06]"));
  EXPECT_TRUE(refused(R"({"grid": {"spacing": 1e300}})", "grid.spacing is 1e+300, outside [1e-06, 1e+06]"));
  const std::string splash = R"({"perturbations": [{"row": 25, "col": 25, )";
  EXPECT_TRUE(refused(splash + R"("radius": 1e9, "amplitude": 1}]})",
                      "perturbations[0].radius is 1e+09 (1e+09 grid spacings), outside [0.001, 1e+06] spacings"));
  EXPECT_TRUE(refused(splash + R"("radius": 1e-300, "amplitude": 1}]})", "perturbations[0].radius is 1e-300"));
  EXPECT_TRUE(refused(R"({"grid": {"spacing": 0.5}, "perturbations": [{"row": 1, "col": 1, "radius": 6e5, "amplitude": 1}]})",
                      "perturbations[0].radius is 600000 (1.2e+06 grid spacings)"));
  EXPECT_TRUE(refused(splash + R"("radius": 2, "amplitude": 1e38}]})",
                      "perturbations[0].amplitude is 1e+38 (4e+37 grid spacings a step), outside [0, 1e+06]"));
  EXPECT_TRUE(refused(splash + R"("radius": 2, "amplitude": -2e6, "target": "position"}]})",
                      "perturbations[0].amplitude is -2e+06 (2e+06 grid spacings)"));
  EXPECT_NO_THROW(parse_scene(splash + R"("radius": 1e6, "amplitude": 1e6, "target": "position"}]})", "x"));
  EXPECT_TRUE(refused(R"({"basin": {"floor_depth": 1e-300}})", "basin.floor_depth is 1e-300"));
  EXPECT_TRUE(refused(R"({"view": {"land_height": 1e300}})", "view.land_height is 1e+300"));
  EXPECT_TRUE(refused(R"({"constraints": [{"kind": "fixed", "rows": [20, 24], "cols": [30, 34]}], "tree": {"height": 1e300}})",
                      "tree.height is 1e+300 (1e+300 grid spacings)"));
  EXPECT_TRUE(refused(R"({"bodies": [{"motion": "kinematic", "radius": 2, "path": [[0, 10, 0, 10], [10, 10, 1e300, 10]]}]})",
                      "bodies[0].path[1] has y 1e+300 (1e+300 grid spacings), outside [-1e+06, 1e+06]"));
  // A floating ball's height: under a tiny gravity no fall is fast, yet 1e300 is no height.
  EXPECT_TRUE(refused(R"({"physics": {"gravity": 1e-300},
                          "bodies": [{"motion": "floating", "radius": 2, "density": 0.5, "position": [10, 1e300, 10]}]})",
                      "bodies[0].position has y 1e+300: higher than 1e+06, a million grid spacings above the land"));
}

TEST(SceneLimits, AnglesCamerasAndPixelsStayRepresentable) {
  EXPECT_TRUE(refused(R"({"wind": {"direction_deg": 1e100}})", "wind.direction_deg is 1e+100, outside [-360, 360] degrees"));
  EXPECT_TRUE(refused(R"({"wind": {"direction_deg": -360.5}})", "wind.direction_deg is -360.5"));
  EXPECT_TRUE(refused(R"({"camera": {"eye": [1e160, 1, 1], "target": [0, 0, 0]}})",
                      "camera.eye has a coordinate that is 1e+160, outside [-1e+15, 1e+15]"));
  EXPECT_TRUE(refused(R"({"camera": {"eye": [1, 1, 1], "target": [0, -2e15, 0]}})", "camera.target has a coordinate"));
  EXPECT_TRUE(refused(R"({"camera": {"eye": [1, 1, 1], "target": [0, 0, 0], "fovy": 1e-300}})",
                      "camera.fovy must be in [0.01, 179.99] degrees"));
  EXPECT_TRUE(refused(R"({"view": {"lod_tolerance": 1e300}})", "view.lod_tolerance is 1e+300, outside [0, 1e+06] pixels"));
}

TEST(SceneLimits, ADensityJustOutsideItsRangeShowsTheDigitsThatMatter) {
  const std::string ball = R"({"bodies": [{"motion": "floating", "radius": 2, "position": [10, 0, 10], )";
  EXPECT_TRUE(refused(ball + R"("density": 100.00001}]})", "bodies[0].density is 100.00001; a floating ball"));
  EXPECT_TRUE(refused(ball + R"("density": 0.0099999}]})", "bodies[0].density is 0.0099999;"));
}

TEST(SceneLimits, ABodysFloatConstantsStayFinite) {
  // Each value in range, together a ball 1.7e31 node masses heavy (its body-to-node ratio overflows
  // float) or a node 4.8e29 ball masses heavy.
  EXPECT_TRUE(refused(R"({"grid": {"spacing": 1e6}, "physics": {"water_density": 1e6, "mass": 1e-6, "gravity": 0,
                          "stiffness": 0, "damping": 0}, "basin": {"floor_depth": 3e6},
                          "bodies": [{"motion": "floating", "radius": 2e6, "density": 0.5, "position": [1e7, 0, 1e7]}]})",
                      "bodies[0].density gives a body-to-node mass ratio (with physics.mass, water_density) of 1.67552e+31"));
  EXPECT_TRUE(refused(R"({"grid": {"spacing": 1e-6}, "physics": {"water_density": 1e-6, "mass": 1e6, "gravity": 0},
                          "basin": {"floor_depth": 3e-6},
                          "bodies": [{"motion": "floating", "radius": 1e-6, "mass": 1e-25, "position": [1e-5, 0, 1e-5]}]})",
                      "bodies[0].mass gives a node-to-body mass ratio (with physics.mass, water_density) of 1e+31"));
}

TEST(SceneLimits, TheSunMeansItsDirectionAtAnyScale) {
  const std::array<double, 3> huge = parse_scene(R"({"lighting": {"sun": [1e200, 1e200, 0]}})", "x").lighting.sun;
  const std::array<double, 3> tiny = parse_scene(R"({"lighting": {"sun": [1e-200, 1e-200, 0]}})", "x").lighting.sun;
  const std::array<double, 3> denormal = parse_scene(R"({"lighting": {"sun": [4e-320, 4e-320, 0]}})", "x").lighting.sun;
  EXPECT_EQ(huge[0], huge[1]);
  EXPECT_EQ(huge[2], 0.0);
  EXPECT_GE(huge[0], 0.5);
  EXPECT_LT(huge[0], 1.0);
  EXPECT_EQ(tiny[0], tiny[1]);
  EXPECT_GE(tiny[0], 0.5);
  EXPECT_EQ(denormal[0], denormal[1]);
  EXPECT_GE(denormal[0], 0.5);
  // A sane direction is kept as written, so every renderer's normalization gives the same bits.
  const std::array<double, 3> sane{-0.3, 0.38, -0.87};
  EXPECT_EQ(parse_scene(R"({"lighting": {"sun": [-0.3, 0.38, -0.87]}})", "x").lighting.sun, sane);
}

}  // namespace
}  // namespace pond::scene
