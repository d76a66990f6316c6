// Scene parsing: the contract's keys, defaults, and one-line errors naming the key's path.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/errors.h"
#include "sim/model.h"
#include "scene/scene.h"

namespace pond::scene {
namespace {

using sim::NodeKind;
using sim::PerturbMode;
using sim::PerturbTarget;
using tree::TreeBend;
using tree::TreeDraw;
using tree::TreeSpec;
using tree::WindSpec;
using view::LightingSpec;
using view::ViewSpec;

// Parses `json` expecting an InputError whose message contains `needle`.
std::string error_of(const std::string& json) {
  try {
    parse_scene(json, "test.json");
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "multi-line message: " << m;
    EXPECT_EQ(m.rfind("test.json: ", 0), 0u) << m;
    return m;
  }
  ADD_FAILURE() << "no error for " << json;
  return "";
}

TEST(Scene, ContractExampleParses) {
  const Scene s = parse_scene(R"({
    "grid":    {"rows": 50, "cols": 40, "spacing": 0.5},
    "physics": {"mass": 4.0, "stiffness": 7.0, "damping": 0.05, "dt": 0.2},
    "border":  "vertical",
    "constraints":   [{"kind": "fixed", "rows": [20, 24], "cols": [30, 34]}],
    "perturbations": [{"step": 3, "row": 25.5, "col": 25, "radius": 2.0, "amplitude": -1.0,
                       "target": "position", "mode": "set"}]})",
                              "x");
  EXPECT_EQ(s.grid.rows, 50);
  EXPECT_EQ(s.grid.cols, 40);
  EXPECT_EQ(s.grid.spacing, 0.5);
  EXPECT_EQ(s.border, NodeKind::vertical);
  ASSERT_EQ(s.constraints.size(), 1u);
  EXPECT_EQ(s.constraints[0].row0, 20);
  EXPECT_EQ(s.constraints[0].col1, 34);
  ASSERT_EQ(s.perturbations.size(), 1u);
  EXPECT_EQ(s.perturbations[0].step, 3);
  EXPECT_EQ(s.perturbations[0].row, 25.5);
  EXPECT_EQ(s.perturbations[0].target, PerturbTarget::position);
  EXPECT_EQ(s.perturbations[0].mode, PerturbMode::set);
}

TEST(Scene, EmptyObjectGivesTableOneDefaults) {
  const Scene s = parse_scene("{}", "x");
  EXPECT_EQ(s.grid.rows, 50);
  EXPECT_EQ(s.grid.cols, 50);
  EXPECT_EQ(s.grid.spacing, 1.0);
  EXPECT_EQ(s.physics.mass, 4.0);
  EXPECT_EQ(s.physics.stiffness, 7.0);
  EXPECT_EQ(s.physics.damping, 0.05);
  EXPECT_EQ(s.physics.dt, 0.4);
  EXPECT_EQ(s.border, NodeKind::fixed);
}

TEST(Scene, DefaultSceneHasAnIslandAndASplash) {
  const Scene s = load_scene("");
  EXPECT_FALSE(s.constraints.empty());
  EXPECT_FALSE(s.perturbations.empty());
}

TEST(Scene, ErrorsNameTheKeyPath) {
  EXPECT_NE(error_of(R"({"grid": {"rows": 1}})").find("grid.rows must be at least 2"), std::string::npos);
  EXPECT_NE(error_of(R"({"grid": {"rows": "50"}})").find("grid.rows must be an integer, not a string"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"grid": {"cols": 2.5}})").find("grid.cols must be an integer"), std::string::npos);
  EXPECT_NE(error_of(R"({"grid": {"spacing": 0}})").find("grid.spacing must be positive"), std::string::npos);
  EXPECT_NE(error_of(R"({"grid": {"rows": 50, "colums": 3}})").find("grid.colums is not a known key"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"gird": {}})").find("gird is not a known key"), std::string::npos);
  EXPECT_NE(error_of(R"({"physics": {"mass": 0}})").find("physics.mass must be positive"), std::string::npos);
  EXPECT_NE(error_of(R"({"physics": {"mass": -1}})").find("physics.mass must be positive"), std::string::npos);
  EXPECT_NE(error_of(R"({"physics": {"stiffness": -1}})").find("physics.stiffness must not be negative"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"physics": {"damping": -0.1}})").find("physics.damping must not be negative"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"physics": {"dt": 0}})").find("physics.dt must be positive"), std::string::npos);
  EXPECT_NE(error_of(R"({"border": "wobbly"})").find("border is 'wobbly', expected fixed | vertical | free"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"constraints": [{"kind": "free", "rows": [1, 2], "cols": [1, 2]}]})")
                .find("constraints[0].kind is 'free', expected fixed | vertical"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"constraints": [{"kind": "fixed", "rows": [1, 50], "cols": [1, 2]}]})")
                .find("constraints[0].rows [1, 50] is out of range [0, 49]"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"constraints": [{"kind": "fixed", "rows": [5, 2], "cols": [1, 2]}]})")
                .find("constraints[0].rows [5, 2] is reversed"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"constraints": [{"kind": "fixed", "rows": [-1, 2], "cols": [1, 2]}]})")
                .find("constraints[0].rows"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"constraints": {"kind": "fixed"}})").find("constraints must be an array"),
            std::string::npos);
  const char* splash = R"({"perturbations": [{"row": 5, "col": 5, "radius": %s, "amplitude": 1%s}]})";
  auto p = [&](const char* radius, const char* extra) {
    char buf[512];
    std::snprintf(buf, sizeof buf, splash, radius, extra);
    return error_of(buf);
  };
  EXPECT_NE(p("0", "").find("perturbations[0].radius must be positive"), std::string::npos);
  EXPECT_NE(p("-2", "").find("perturbations[0].radius must be positive"), std::string::npos);
  EXPECT_NE(p("1", R"(, "target": "height")").find("perturbations[0].target is 'height'"), std::string::npos);
  EXPECT_NE(p("1", R"(, "mode": "mul")").find("perturbations[0].mode is 'mul'"), std::string::npos);
  EXPECT_NE(p("1", R"(, "step": -1)").find("perturbations[0].step must be at least 0"), std::string::npos);
  EXPECT_NE(error_of(R"({"perturbations": [{"row": 5, "col": 5, "radius": 1}]})")
                .find("perturbations[0].amplitude is missing"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"perturbations": [{"row": 50, "col": 5, "radius": 1, "amplitude": 1}]})")
                .find("perturbations[0].row is outside the grid"),
            std::string::npos);
}

TEST(Scene, MalformedJsonIsOneLine) {
  EXPECT_NE(error_of(R"({"grid": {"rows": 50,)").find("invalid JSON"), std::string::npos);
  EXPECT_NE(error_of("").find("invalid JSON"), std::string::npos);
  EXPECT_NE(error_of("[1, 2]").find("must be an object"), std::string::npos);
}

TEST(Scene, HugeGridIsRefusedBeforeAllocating) {
  EXPECT_NE(error_of(R"({"grid": {"rows": 65536, "cols": 65536}})").find("more than this machine's memory"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"grid": {"rows": 100000, "cols": 10}})").find("grid.rows must be at most"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"grid": {"rows": 1e300, "cols": 10}})").find("grid.rows"), std::string::npos);
}

TEST(Scene, UnstableTimeStepIsRefusedWithTheBound) {
  // Table 1: m = 4, c = 7, gamma = 0.05: the bound is 0.5324...
  const std::string m = error_of(R"({"physics": {"dt": 0.6}})");
  EXPECT_NE(m.find("physics.dt 0.6 exceeds the semi-implicit Euler stability bound 0.53363"), std::string::npos) << m;
  EXPECT_NE(m.find("physics.substeps >= 2"), std::string::npos) << m;
  // Substeps that bring it inside are accepted.
  const Scene s = parse_scene(R"({"physics": {"dt": 0.6, "substeps": 2}})", "x");
  EXPECT_EQ(s.physics.substeps, 2);
  // Stiffer springs lower the bound.
  EXPECT_NE(error_of(R"({"physics": {"stiffness": 20}})").find("stability bound"), std::string::npos);
}


// The rendering keys (pond render, the demo): camera, view, lighting.
TEST(Scene, RenderKeysParse) {
  const Scene s = parse_scene(R"({"camera": {"eye": [1, 2, 3], "target": [4, 0, 5], "fovy": 50},
                                  "view": {"steps_per_frame": 3, "lod_tolerance": 0, "floor_depth": 2.5,
                                           "land_height": 1, "reflections": false, "caustics": false,
                                           "shadows": false, "submerged": false},
                                  "lighting": {"sun": [0, 1, 0], "water": [0, 0.1, 0.2], "sky": [1, 1, 1],
                                               "ground": [0.5, 0.5, 0.5]}})",
                              "x");
  ASSERT_TRUE(s.camera.has_value());
  EXPECT_EQ(s.camera->eye, (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(s.camera->target, (std::array<double, 3>{4, 0, 5}));
  EXPECT_EQ(s.camera->fovy_degrees, 50);
  EXPECT_EQ(s.view.steps_per_frame, 3);
  EXPECT_EQ(s.view.lod_tolerance_px, 0);
  EXPECT_EQ(s.basin.floor_depth, 2.5);  // the keys' old place still works
  EXPECT_EQ(s.basin.land_height, 1);
  EXPECT_FALSE(s.view.effects.reflections);
  EXPECT_FALSE(s.view.effects.caustics);
  EXPECT_FALSE(s.view.effects.shadows);
  EXPECT_FALSE(s.view.effects.submerged);
  EXPECT_EQ(s.lighting.sun, (std::array<double, 3>{0, 1, 0}));
  EXPECT_EQ(s.lighting.sky, (std::array<double, 3>{1, 1, 1}));
  EXPECT_EQ(s.lighting.absorption, (view::LightingSpec{}.absorption));  // not given: pure water's
  // Absent: no camera (the renderer frames the pond), defaults elsewhere.
  const Scene d = parse_scene("{}", "x");
  EXPECT_FALSE(d.camera.has_value());
  EXPECT_EQ(d.view.steps_per_frame, ViewSpec{}.steps_per_frame);
  EXPECT_EQ(d.view.lod_tolerance_px, ViewSpec{}.lod_tolerance_px);
  EXPECT_TRUE(d.view.effects.reflections);  // the effects default on
  EXPECT_TRUE(d.view.effects.caustics);
  EXPECT_TRUE(d.view.effects.shadows);
  EXPECT_TRUE(d.view.effects.submerged);
}

TEST(Scene, RenderKeyErrorsNameThePath) {
  auto has = [](const char* json, const char* text) {
    const std::string m = error_of(json);
    return m.find(text) != std::string::npos ? ::testing::AssertionSuccess()
                                             : ::testing::AssertionFailure() << m;
  };
  EXPECT_TRUE(has(R"({"camera": {"eye": [1, 2], "target": [0, 0, 0]}})", "camera.eye must be an array of three numbers"));
  EXPECT_TRUE(has(R"({"camera": {"eye": [1, 2, "3"], "target": [0, 0, 0]}})", "camera.eye must be an array of three"));
  EXPECT_TRUE(has(R"({"camera": {"eye": 3, "target": [0, 0, 0]}})", "camera.eye must be an array, not a number"));
  EXPECT_TRUE(has(R"({"camera": {"target": [0, 0, 0]}})", "camera.eye is missing"));
  EXPECT_TRUE(has(R"({"camera": {"eye": [0, 0, 0], "target": [0, 0, 0]}})", "camera.target must differ"));
  EXPECT_TRUE(has(R"({"camera": {"eye": [0, 1, 0], "target": [0, 0, 0], "fovy": 180}})", "camera.fovy must be in [0.01, 179.99]"));
  EXPECT_TRUE(has(R"({"camera": {"eye": [0, 1, 0], "target": [0, 0, 0], "fov": 60}})", "camera.fov is not a known key"));
  EXPECT_TRUE(has(R"({"camera": [1, 2, 3]})", "camera must be an object, not an array"));
  EXPECT_TRUE(has(R"({"view": {"steps_per_frame": -1}})", "view.steps_per_frame must be at least 0"));
  EXPECT_TRUE(has(R"({"view": {"steps_per_frame": 1.5}})", "view.steps_per_frame must be an integer"));
  EXPECT_TRUE(has(R"({"view": {"lod_tolerance": -1}})", "view.lod_tolerance must not be negative"));
  EXPECT_TRUE(has(R"({"view": {"lod_tolerance": "1"}})", "view.lod_tolerance must be a number, not a string"));
  EXPECT_TRUE(has(R"({"view": {"floor_depth": 0}})", "view.floor_depth must be positive (it is basin.floor_depth now)"));
  EXPECT_TRUE(has(R"({"view": {"land_height": -1}})", "view.land_height must be positive (it is basin.land_height now)"));
  EXPECT_TRUE(has(R"({"basin": {"floor_depth": 0}})", "basin.floor_depth must be positive"));
  EXPECT_TRUE(has(R"({"basin": {"land_height": 2}, "view": {"land_height": 2}})",
                  "view.land_height is given twice: it is basin.land_height now"));
  EXPECT_TRUE(has(R"({"basin": {"depth": 2}})", "basin.depth is not a known key"));
  EXPECT_TRUE(has(R"({"view": {"wireframe": true}})", "view.wireframe is not a known key"));
  EXPECT_TRUE(has(R"({"view": {"reflections": 1}})", "view.reflections must be true or false, not a number"));
  EXPECT_TRUE(has(R"({"view": {"reflections": "on"}})", "view.reflections must be true or false, not a string"));
  EXPECT_TRUE(has(R"({"view": {"caustics": 0}})", "view.caustics must be true or false, not a number"));
  EXPECT_TRUE(has(R"({"view": {"caustics": null}})", "view.caustics must be true or false"));
  EXPECT_TRUE(has(R"({"view": {"shadows": 0}})", "view.shadows must be true or false, not a number"));
  EXPECT_TRUE(has(R"({"view": {"shadows": null}})", "view.shadows must be true or false"));
  EXPECT_TRUE(has(R"({"view": {"submerged": "yes"}})", "view.submerged must be true or false"));
  EXPECT_TRUE(has(R"({"lighting": {"sun": [0, 0, 0]}})", "lighting.sun must not be zero"));
  EXPECT_TRUE(has(R"({"lighting": {"water": [0, 2, 0]}})", "lighting.water must be an RGB colour"));
  EXPECT_TRUE(has(R"({"lighting": {"sky": "blue"}})", "lighting.sky must be an array"));
  EXPECT_TRUE(has(R"({"lighting": {"absorption": [0.3, -0.1, 0]}})", "lighting.absorption must be three coefficients"));
  EXPECT_TRUE(has(R"({"lighting": {"absorption": [0.3, 1000, 0]}})", "lighting.absorption must be three coefficients"));
  EXPECT_TRUE(has(R"({"lighting": {"moon": [0, 1, 0]}})", "lighting.moon is not a known key"));
}

TEST(Scene, TreeAndWindKeysParse) {
  const Scene s = parse_scene(R"({"tree": {"depth": 6, "seed": 7, "height": 4.5, "positions": [[10, 12.5], [30, 31]],
                                           "bend": "keep-length", "draw": "lines", "leaves": false},
                                  "wind": {"strength": 5, "direction_deg": 90, "seed": 3, "ripples": true}})",
                              "x");
  ASSERT_TRUE(s.tree.has_value());
  EXPECT_EQ(s.tree->depth, 6);
  EXPECT_EQ(s.tree->seed, 7u);
  EXPECT_EQ(s.tree->height, 4.5);
  ASSERT_EQ(s.tree->positions.size(), 2u);
  EXPECT_EQ(s.tree->positions[0], (std::array<double, 2>{10, 12.5}));
  EXPECT_EQ(s.tree->bend, TreeBend::keep_length);
  EXPECT_EQ(s.tree->draw, TreeDraw::lines);
  EXPECT_FALSE(s.tree->leaves);
  EXPECT_EQ(s.wind.strength, 5);
  EXPECT_EQ(s.wind.direction_deg, 90);
  EXPECT_EQ(s.wind.seed, 3u);
  EXPECT_TRUE(s.wind.ripples);
  // Absent: no tree, the default wind (which ripples nothing).
  const Scene d = parse_scene("{}", "x");
  EXPECT_FALSE(d.tree.has_value());
  EXPECT_FALSE(d.wind.ripples);
  EXPECT_EQ(d.wind.strength, WindSpec{}.strength);
  // An empty "tree" stands on the centre of the first fixed constraint, with the defaults.
  const Scene i = parse_scene(R"({"constraints": [{"kind": "vertical", "rows": [1, 2], "cols": [1, 2]},
                                                  {"kind": "fixed", "rows": [30, 35], "cols": [30, 36]}],
                                  "tree": {}})", "x");
  ASSERT_TRUE(i.tree.has_value());
  ASSERT_EQ(i.tree->positions.size(), 1u);
  EXPECT_EQ(i.tree->positions[0], (std::array<double, 2>{32.5, 33}));
  EXPECT_EQ(i.tree->depth, TreeSpec{}.depth);
  EXPECT_EQ(i.tree->bend, TreeBend::article);
  EXPECT_EQ(i.tree->draw, TreeDraw::tubes);
  EXPECT_TRUE(i.tree->leaves);
}

TEST(Scene, TreeAndWindErrorsNameThePath) {
  auto has = [](const char* json, const char* text) {
    const std::string m = error_of(json);
    return m.find(text) != std::string::npos ? ::testing::AssertionSuccess()
                                             : ::testing::AssertionFailure() << m;
  };
  const char* island = R"("constraints": [{"kind": "fixed", "rows": [30, 35], "cols": [30, 36]}])";
  auto with_island = [&](const std::string& tree) { return "{" + std::string(island) + ", " + tree + "}"; };
  EXPECT_TRUE(has(with_island(R"("tree": {"depth": 11})").c_str(), "tree.depth must be at most 10"));
  EXPECT_TRUE(has(with_island(R"("tree": {"depth": 0})").c_str(), "tree.depth must be at least 1"));
  EXPECT_TRUE(has(with_island(R"("tree": {"height": 0})").c_str(), "tree.height must be positive"));
  EXPECT_TRUE(has(with_island(R"("tree": {"bend": "stiff"})").c_str(), "tree.bend is 'stiff', expected article | keep-length"));
  EXPECT_TRUE(has(with_island(R"("tree": {"draw": "points"})").c_str(), "tree.draw is 'points', expected lines | tubes"));
  EXPECT_TRUE(has(with_island(R"("tree": {"leaves": 1})").c_str(), "tree.leaves must be true or false, not a number"));
  EXPECT_TRUE(has(with_island(R"("tree": {"positions": [[1, 2, 3]]})").c_str(), "tree.positions[0] must be a grid position [row, col]"));
  EXPECT_TRUE(has(with_island(R"("tree": {"positions": [[1, 2], [50, 2]]})").c_str(), "tree.positions[1] is outside the grid [0, 49] x [0, 49]"));
  EXPECT_TRUE(has(with_island(R"("tree": {"instances": 3})").c_str(), "tree.instances is not a known key"));
  EXPECT_TRUE(has(with_island(R"("tree": true)").c_str(), "tree must be an object, not a boolean"));
  EXPECT_TRUE(has(R"({"tree": {}})", "tree.positions is missing and the scene has no fixed constraint"));
  EXPECT_TRUE(has(R"({"wind": {"strength": 10}})", "wind.strength must be in [0, 9]"));
  EXPECT_TRUE(has(R"({"wind": {"direction_deg": "north"}})", "wind.direction_deg must be a number, not a string"));
  EXPECT_TRUE(has(R"({"wind": {"ripples": "yes"}})", "wind.ripples must be true or false, not a string"));
  EXPECT_TRUE(has(R"({"wind": {"speed": 3}})", "wind.speed is not a known key"));
}

TEST(Scene, BodiesParse) {
  const Scene s = parse_scene(R"({
    "grid": {"rows": 50, "cols": 40, "spacing": 0.5}, "physics": {"gravity": 0.1},
    "bodies": [{"shape": "sphere", "radius": 3.0, "motion": "kinematic",
                "path": [[0, 10.0, 0.5, 12.0], [300, 15.0, 0.5, 12.0]]},
               {"radius": 2.0, "motion": "floating", "mass": 30.0, "position": [15.0, 2.0, 20.0],
                "velocity": [0.5, 0.0, 0.0]}]})", "test.json");
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[0].motion, sim::BodyMotion::kinematic);
  ASSERT_EQ(s.bodies[0].path.size(), 2u);
  EXPECT_EQ(s.bodies[0].path[1].step, 300);
  EXPECT_EQ(s.bodies[0].path[1].position[0], 15.0);
  EXPECT_EQ(s.bodies[1].motion, sim::BodyMotion::floating);
  EXPECT_EQ(s.bodies[1].mass, 30.0);
  EXPECT_EQ(s.bodies[1].velocity[0], 0.5);
  EXPECT_EQ(s.physics.gravity, 0.1);
  EXPECT_EQ(parse_scene("{}", "test.json").physics.gravity, 0.05);  // the documented default
}

TEST(Scene, BodyErrorsNameThePath) {
  auto has = [](const std::string& bodies, const char* text) {
    const std::string m = error_of(R"({"grid": {"rows": 50, "cols": 40}, "bodies": [)" + bodies + "]}");
    return m.find(text) != std::string::npos ? ::testing::AssertionSuccess() : ::testing::AssertionFailure() << m;
  };
  const std::string ball = R"({"motion": "floating", "mass": 3, "position": [5, 1, 5], )";
  EXPECT_TRUE(has(ball + R"("radius": 0})", "bodies[0].radius must be positive"));
  EXPECT_TRUE(has(ball + R"("radius": -2})", "bodies[0].radius must be positive"));
  EXPECT_TRUE(has(ball + R"("radius": 0.5})", "bodies[0].radius is 0.5, less than the grid spacing 1"));
  EXPECT_TRUE(has(R"({"motion": "floating", "mass": 0, "position": [5, 1, 5], "radius": 2})",
                  "bodies[0].mass must be positive"));
  EXPECT_TRUE(has(R"({"motion": "floating", "mass": -1, "position": [5, 1, 5], "radius": 2})",
                  "bodies[0].mass must be positive"));
  EXPECT_TRUE(has(R"({"motion": "floating", "position": [5, 1, 5], "radius": 2})", "bodies[0].mass is missing"));
  EXPECT_TRUE(has(R"({"motion": "floating", "mass": 3, "position": [40, 1, 5], "radius": 2})",
                  "bodies[0].position is outside the grid: x must be in [0, 39] and z in [0, 49]"));
  EXPECT_TRUE(has(R"({"motion": "floating", "mass": 3, "position": [5, 1, -0.5], "radius": 2})",
                  "bodies[0].position is outside the grid"));
  EXPECT_TRUE(has(ball + R"("radius": 2, "shape": "cube"})", "bodies[0].shape is 'cube', expected sphere"));
  EXPECT_TRUE(has(R"({"motion": "sinking", "mass": 3, "position": [5, 1, 5], "radius": 2})",
                  "bodies[0].motion is 'sinking', expected kinematic | floating"));
  EXPECT_TRUE(has(R"({"radius": 2, "mass": 3, "position": [5, 1, 5]})", "bodies[0].motion is missing"));
  EXPECT_TRUE(has(ball + R"("radius": 2, "colour": "red"})", "bodies[0].colour is not a known key"));
  EXPECT_TRUE(has(ball + R"("radius": 2}, {"motion": "kinematic", "radius": 2, "path": [[0, 1, 0, 1], [10, 2, 0, 2], [5, 3, 0, 3]]})",
                  "bodies[1].path[2] has step 5, not after the key before it (step 10): steps must increase"));
  EXPECT_TRUE(has(R"({"motion": "kinematic", "radius": 2, "path": [[0, 1, 0, 1], [0, 2, 0, 2]]})",
                  "bodies[0].path[1] has step 0, not after"));
  EXPECT_TRUE(has(R"({"motion": "kinematic", "radius": 2, "path": [[0, 1, 0, 1], [10, 2, 0, 60]]})",
                  "bodies[0].path[1] is outside the grid"));
  EXPECT_TRUE(has(R"({"motion": "kinematic", "radius": 2, "path": [[-1, 1, 0, 1]]})",
                  "bodies[0].path[0] has step -1: a step must be an integer >= 0"));
  EXPECT_TRUE(has(R"({"motion": "kinematic", "radius": 2, "path": [[0.5, 1, 0, 1]]})", "bodies[0].path[0] has step 0.5"));
  EXPECT_TRUE(has(R"({"motion": "kinematic", "radius": 2, "path": [[0, 1, 0]]})",
                  "bodies[0].path[0] must be a key [step, x, y, z] of four numbers"));
  EXPECT_TRUE(has(R"({"motion": "kinematic", "radius": 2})", "bodies[0].path is missing"));
  EXPECT_TRUE(has(R"({"motion": "kinematic", "radius": 2, "path": []})", "bodies[0].path is empty"));
  EXPECT_TRUE(has(R"({"motion": "kinematic", "radius": 2, "mass": 3, "path": [[0, 1, 0, 1]]})",
                  "bodies[0].mass is for floating bodies"));
  EXPECT_TRUE(has(ball + R"("radius": 2, "path": [[0, 1, 0, 1]]})", "bodies[0].path is for kinematic bodies"));
  EXPECT_TRUE(has(R"(3)", "bodies[0] must be an object, not a number"));
  EXPECT_TRUE(error_of(R"({"physics": {"gravity": -1}})").find("physics.gravity must be finite and not negative") !=
              std::string::npos);
}

}  // namespace
}  // namespace pond::scene

// Every scene shipped in scenes/ loads and builds a model (a broken example would be the first
// thing a reader runs into).
TEST(Scene, ShippedScenesLoadAndBuild) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(POND_SCENES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const pond::scene::Scene scene = pond::scene::load_scene(entry.path().string());
    EXPECT_NO_THROW(pond::sim::build_model(scene));
    ++count;
  }
  EXPECT_GE(count, 8);
}
