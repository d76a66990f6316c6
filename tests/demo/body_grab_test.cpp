// The demo's hold on a body (src/app/demo/body_grab.h) on a CPU session, no window: a ray through a
// ball grabs it and one that misses every body grabs nothing; dragged along +x frame by frame the
// ball follows the cursor and is held; let go, it floats on along +x with about the drag's speed.
#include <gtest/gtest.h>

#include <cmath>

#include "app/demo/body_grab.h"
#include "scene/scene.h"
#include "scene/session_spec.h"

namespace pond::app::demo {
namespace {

// A still pond with one floating ball at (20, 1.5, 20) (world, spacing 1), seen from above.
const char* kBall = R"({"grid": {"rows": 41, "cols": 41}, "physics": {"gravity": 0.05},
  "bodies": [{"shape": "sphere", "radius": 2.5, "motion": "floating", "mass": 30.0,
              "position": [20.0, 1.5, 20.0]}]})";

lod::Camera above() {
  lod::Camera c;
  c.eye = {20.0, 60.0, 30.0};
  c.target = {20.0, 0.0, 20.0};
  c.fovy_degrees = 45;
  c.width = 400, c.height = 400;
  return c;
}

TEST(BodyGrab, DragsAFloatingBallAndLetsItGoWithTheDragsVelocity) {
  sim::Session session(scene::session_spec(scene::parse_scene(kBall, "test")), sim::SolverChoice{.gpu = false});
  const lod::Camera camera = above();
  BodyGrab grab;
  EXPECT_FALSE(grab.grab(session, pixel_ray(camera, 5, 5)).has_value());  // the corner: water only
  const std::optional<std::size_t> b = grab.grab(session, pixel_ray(camera, 200, 200));
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(*b, 0u);
  const double x0 = session.bodies()[0].x;
  // 20 frames of one step, the cursor 3 pixels to the right each frame.
  for (int f = 1; f <= 20; ++f) {
    grab.move_cursor(200 + 3 * f, 200);
    grab.drag(session, camera, 1);
    session.advance(1);
    EXPECT_TRUE(session.held(0));
  }
  const sim::BodyState held = session.bodies()[0];
  EXPECT_GT(held.x - x0, 3.0);           // it followed the cursor to the right
  EXPECT_NEAR(held.z, 20.0, 0.5);        // and not sideways
  const std::array<double, 3> v = grab.release(session);
  EXPECT_FALSE(grab.active());
  EXPECT_FALSE(session.held(0));
  EXPECT_EQ(session.water().bodies[0].motion, sim::BodyMotion::floating);
  // The drag's velocity: its displacement a frame over a step's time, along +x.
  const double per_step = (held.x - x0) / 20.0 / session.water().physics.dt;
  EXPECT_NEAR(v[0], per_step, 0.25 * per_step);
  EXPECT_EQ(v[1], 0.0);
  EXPECT_NEAR(v[2], 0.0, 0.05 * per_step);
  session.advance(5);
  EXPECT_GT(session.bodies()[0].x, held.x);  // it glides on
}

// The wheel raises the held ball: let go while rising, it is thrown upward (the vertical drag's
// velocity), and falls back to float.
TEST(BodyGrab, ALiftedBallIsThrownWithTheVerticalVelocity) {
  sim::Session session(scene::session_spec(scene::parse_scene(kBall, "test")), sim::SolverChoice{.gpu = false});
  const lod::Camera camera = above();
  BodyGrab grab;
  ASSERT_TRUE(grab.grab(session, pixel_ray(camera, 200, 200)).has_value());
  const double y0 = session.bodies()[0].y;
  for (int f = 1; f <= 10; ++f) {
    grab.lift(0.5);  // a wheel step of half a spacing a frame
    grab.drag(session, camera, 1);
    session.advance(1);
  }
  EXPECT_GT(session.bodies()[0].y - y0, 3.0);
  const std::array<double, 3> v = grab.release(session);
  const double per_step = 0.5 / session.water().physics.dt;
  EXPECT_NEAR(v[1], per_step, 0.25 * per_step);
  session.advance(1);
  EXPECT_GT(session.bodies()[0].vy, 0.0f) << "thrown upward";
}

// Removing bodies keeps the hold on the same body, or ends it when that body goes: a body removed
// after the held one leaves its index alone; one removed before it shifts the index down by one,
// and the body dragged on is still the one grabbed (the same radius, following the cursor).
TEST(BodyGrab, FollowsRemovedBodies) {
  sim::Session session(scene::session_spec(scene::parse_scene(kBall, "test")), sim::SolverChoice{.gpu = false});
  session.add_body({.shape = sim::BodyShape::sphere, .motion = sim::BodyMotion::floating, .radius = 2.0, .mass = 30.0,
                    .position = {30.0, 1.5, 30.0}, .velocity = {}, .path = {}});
  session.add_body({.shape = sim::BodyShape::sphere, .motion = sim::BodyMotion::floating, .radius = 1.5, .mass = 20.0,
                    .position = {10.0, 1.5, 10.0}, .velocity = {}, .path = {}});
  // Seen from above body 1, the second ball (radius 2).
  lod::Camera camera = above();
  camera.eye = {30.0, 60.0, 40.0};
  camera.target = {30.0, 0.0, 30.0};
  BodyGrab grab;
  ASSERT_EQ(grab.grab(session, pixel_ray(camera, 200, 200)), std::optional<std::size_t>(1));
  session.remove_body(2);
  grab.body_removed(2);  // after the held one: no change
  ASSERT_TRUE(grab.active());
  EXPECT_EQ(grab.index(), 1u);
  session.remove_body(0);
  grab.body_removed(0);  // before it: the held ball is body 0 now
  ASSERT_TRUE(grab.active());
  ASSERT_EQ(grab.index(), 0u);
  ASSERT_EQ(session.water().bodies.size(), 1u);
  EXPECT_EQ(session.water().bodies[grab.index()].radius, 2.0);
  const double x0 = session.bodies()[0].x;
  for (int f = 1; f <= 10; ++f) {
    grab.move_cursor(200 + 3 * f, 200);
    grab.drag(session, camera, 1);
    session.advance(1);
  }
  EXPECT_TRUE(session.held(0));
  EXPECT_GT(session.bodies()[0].x - x0, 1.5) << "the held ball follows the cursor";
  grab.body_removed(0);  // the held one itself: the hold ends
  EXPECT_FALSE(grab.active());
}

TEST(BodyGrab, TheWheelLiftsAHeldBallNoHigherThanAPondAboveTheLand) {
  sim::Session session(scene::session_spec(scene::parse_scene(kBall, "test")), sim::SolverChoice{.gpu = false});
  const lod::Camera camera = above();
  BodyGrab grab;
  ASSERT_TRUE(grab.grab(session, pixel_ray(camera, 200, 200)).has_value());
  const double land = session.model().basin.land_height, pond = 41.0, floor = session.model().basin.floor_depth;
  grab.lift(1e30);
  for (int f = 0; f < 200; ++f) grab.drag(session, camera, 1), session.advance(1);
  const double top = session.bodies()[0].y;  // spacing 1: world units
  EXPECT_TRUE(std::isfinite(top));
  EXPECT_LE(top, land + pond + 1e-3);
  EXPECT_GT(top, land + pond - 1.0);  // it got there
  grab.lift(-1e30);
  for (int f = 0; f < 200; ++f) grab.drag(session, camera, 1), session.advance(1);
  EXPECT_GE(session.bodies()[0].y, -floor - 1e-3);
}

}  // namespace
}  // namespace pond::app::demo
