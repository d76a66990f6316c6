// The simulation session (sim/session.h) on the CPU: it runs the scene as the solver does, its
// edits are checked by the scene file's own checks, splashes equal scene perturbations, the water
// carries over new constraints and solver switches, the wind ripples land whether or not a run
// passes their horizon, and a blow-up is reported naming the node.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

#include "core/errors.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"
#include "sim/session.h"
#include "sim/wind_ripples.h"

namespace pond::sim {
namespace {

const SolverChoice kScalar{.gpu = false, .backend = Backend::scalar, .threads = 1};

std::uint64_t hash(Session& s) { return state_hash(s.state(), s.model()); }

std::uint64_t solver_hash(const WaterSpec& water, std::int64_t steps) {
  CpuSolver solver(build_model(water), Backend::scalar, 1);
  solver.advance(steps);
  return state_hash(solver.state(), solver.model());
}

// The message a scene file gets for these physics, without its "file: " prefix.
std::string scene_message(const std::string& physics_json) {
  try {
    scene::parse_scene("{\"physics\": " + physics_json + "}", "f");
  } catch (const InputError& e) {
    return std::string(e.what()).substr(3);  // "f: "
  }
  return "";
}

std::string edit_message(Session& s, const Physics& p) {
  try {
    s.set_physics(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Session, AdvancesAsTheSolverDoes) {
  Session s(scene::session_spec(scene::load_scene("")), kScalar);
  s.advance(300);
  s.advance(0);
  s.advance(200);
  EXPECT_EQ(s.steps_done(), 500);
  EXPECT_EQ(hash(s), solver_hash(scene::load_scene(""), 500));
}

TEST(Session, PhysicsEditsAreCheckedLikeSceneFiles) {
  Session s(scene::session_spec(scene::load_scene("")), kScalar);
  s.advance(10);
  const std::uint64_t before = hash(s);
  struct Case {
    Physics physics;
    const char* json;
  };
  const Case cases[] = {
      {{.mass = -1}, R"({"mass": -1})"},
      {{.stiffness = -2}, R"({"stiffness": -2})"},
      {{.rest_ratio = 0}, R"({"rest_ratio": 0})"},
      {{.dt = 0.6}, R"({"dt": 0.6})"},  // past the stability bound 0.5336
      {{.dt = 2.0, .substeps = 3}, R"({"dt": 2.0, "substeps": 3})"},
  };
  for (const Case& c : cases) {
    const std::string expected = scene_message(c.json);
    ASSERT_FALSE(expected.empty()) << c.json;
    EXPECT_EQ(edit_message(s, c.physics), expected) << c.json;
  }
  // Refused edits change nothing; an accepted one rebuilds the model with the state carried over.
  EXPECT_EQ(hash(s), before);
  EXPECT_EQ(s.water().physics.dt, 0.4);
  EXPECT_EQ(edit_message(s, {.dt = 2.0, .substeps = 4}), "");
  EXPECT_EQ(s.model().substeps, 4);
  EXPECT_EQ(s.steps_done(), 10);
  EXPECT_EQ(hash(s), before);
}

TEST(Session, SplashEqualsTheScenePerturbation) {
  scene::Scene calm = scene::load_scene("");
  const Perturbation p = calm.perturbations.at(0);
  ASSERT_EQ(p.step, 0);
  calm.perturbations.clear();
  Session s(scene::session_spec(calm), kScalar);
  s.splash(p);
  s.advance(40);
  EXPECT_EQ(hash(s), solver_hash(scene::load_scene(""), 40));
}

TEST(Session, SwitchingBackendsCarriesTheStateAndResetReplays) {
  Session s(scene::session_spec(scene::load_scene("")), kScalar);
  s.advance(100);
  s.set_solver({.gpu = false, .backend = best_backend(), .threads = 2});
  s.advance(100);
  EXPECT_EQ(hash(s), solver_hash(scene::load_scene(""), 200));
  const std::uint64_t revision = s.state_revision(), generation = s.solver_generation();
  s.reset();
  EXPECT_GT(s.state_revision(), revision);
  EXPECT_GT(s.solver_generation(), generation);
  EXPECT_EQ(s.steps_done(), 0);
  s.advance(200);
  EXPECT_EQ(hash(s), solver_hash(scene::load_scene(""), 200));
}

TEST(Session, NewConstraintsHoldTheCarriedWaterAtOnce) {
  Session s(scene::session_spec(scene::load_scene("")), kScalar);
  s.advance(30);
  WaterSpec walled = s.water();
  walled.border = NodeKind::fixed;
  walled.constraints = {{.kind = NodeKind::fixed, .row0 = 20, .row1 = 30, .col0 = 20, .col1 = 30}};
  s.set_water(walled);
  EXPECT_EQ(s.steps_done(), 30);
  const WaterState w = s.state();
  const std::size_t n = 25 * static_cast<std::size_t>(s.model().cols) + 25;
  EXPECT_EQ(w.uy[n], 0.0f);
  EXPECT_EQ(w.vy[n], 0.0f);
  WaterSpec other_grid = walled;
  other_grid.grid.rows += 1;
  EXPECT_THROW(s.set_water(other_grid), InternalError);
}

TEST(Session, WindRipplesLandPastTheirHorizon) {
  const char* small = R"({"grid": {"rows": 12, "cols": 14}, "wind": {"strength": 7, "ripples": true}})";
  const scene::Scene scene = scene::parse_scene(small, "test");
  // What `pond render` used to do: every ripple up to the end, with the scene's perturbations.
  WaterSpec all = scene;
  add_wind_ripples(all, scene.wind, 40000);
  Session s(scene::session_spec(scene), kScalar);
  s.advance(16000);
  s.advance(1000);  // past the first horizon (16384): the solver is rebuilt with the next ripples
  EXPECT_EQ(hash(s), solver_hash(all, 17000));
  const std::uint64_t without = [] {
    Session calm(scene::session_spec(scene::parse_scene(R"({"grid": {"rows": 12, "cols": 14}, "wind": {"strength": 7}})", "test")), kScalar);
    calm.advance(17000);
    return hash(calm);
  }();
  EXPECT_NE(hash(s), without);
}

TEST(Session, BlowUpIsReportedNamingTheNode) {
  Session s(scene::session_spec(scene::load_scene("")), kScalar);
  WaterState w = s.state();
  w.vy[3 * 50 + 7] = std::numeric_limits<float>::infinity();
  s.set_state(w, 5);
  try {
    s.finite_state();
    FAIL() << "no blow-up reported";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("blew up (non-finite velocity at node row 3, col 7)"), std::string::npos)
        << e.what();
  }
}

// Bodies added and removed at run time: the water and the other bodies carry over; a held body
// follows the drag, and a released floating body falls from where it was let go with the drag's
// velocity; a refused body changes nothing; reset gives the scene's bodies back.
TEST(Session, BodiesAreAddedDraggedReleasedAndRemoved) {
  scene::Scene scene = scene::parse_scene(R"({"grid": {"rows": 33, "cols": 33},
    "perturbations": [{"step": 0, "row": 16, "col": 16, "radius": 2.0, "amplitude": 1.0}],
    "bodies": [{"motion": "floating", "radius": 2.0, "mass": 20, "position": [8, 2, 8]}]})", "f");
  Session session(scene::session_spec(scene), kScalar);
  session.advance(20);
  const WaterState before = session.state();
  BodySpec ball;
  ball.radius = 2.5;
  ball.mass = 10;
  ball.position = {24.0, 3.0, 24.0};
  session.add_body(ball);
  ASSERT_EQ(session.bodies().size(), 2u);
  EXPECT_EQ(std::memcmp(session.state().uy.data(), before.uy.data(), before.nodes() * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(&session.bodies()[0], &before.bodies[0], sizeof(BodyState)), 0);
  EXPECT_EQ(session.bodies()[1].x, 24.0f);

  BodySpec off_grid = ball;
  off_grid.position = {40.0, 3.0, 24.0};
  EXPECT_THROW(session.add_body(off_grid), InputError);
  BodySpec tiny = ball;
  tiny.radius = 0.5;
  EXPECT_THROW(session.add_body(tiny), InputError);
  try {  // the scene file's check (scene::body_problem), naming the key the body would have
    session.add_body(tiny);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bodies[2].radius is 0.5, less than the grid spacing 1"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(session.bodies().size(), 2u);

  session.drag_body(1, {20.0, 1.0, 20.0}, 10);
  EXPECT_TRUE(session.held(1));
  session.advance(10);
  EXPECT_NEAR(session.bodies()[1].x, 20.0f, 1e-4);
  EXPECT_NEAR(session.bodies()[1].y, 1.0f, 1e-4);
  session.release_body(1, {0.5, 0.0, 0.0});
  EXPECT_FALSE(session.held(1));
  EXPECT_EQ(session.water().bodies[1].motion, BodyMotion::floating);
  session.advance(4);
  EXPECT_GT(session.bodies()[1].x, 20.5f) << "released with the drag's velocity";

  session.remove_body(0);
  ASSERT_EQ(session.bodies().size(), 1u);
  EXPECT_EQ(session.water().bodies[0].radius, 2.5);
  session.reset();
  EXPECT_EQ(session.bodies().size(), 1u);  // the edits stay; the state starts over
  EXPECT_EQ(session.steps_done(), 0);
}

TEST(Session, GpuWithoutAFactoryIsRefused) {
  EXPECT_THROW(Session(scene::session_spec(scene::load_scene("")), SolverChoice{.gpu = true}), InternalError);
}

}  // namespace
}  // namespace pond::sim
