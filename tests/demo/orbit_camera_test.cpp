// The demo's orbit camera (src/app/demo/orbit_camera.h) stays above the water however far the
// wheel zooms in or the drag orbits down.
#include <gtest/gtest.h>

#include "app/demo/orbit_camera.h"

namespace pond::app::demo {
namespace {

// The default camera of a 50 x 50 pond (view::scene_camera): its target lies below the rest plane.
lod::Camera home() {
  return lod::Camera{.eye = {20.58, 14.7, 63.7}, .target = {24.5, -2.94, 19.6}, .fovy_degrees = 45, .width = 640, .height = 360};
}

TEST(OrbitCamera, ZoomingInKeepsTheEyeAboveTheLowestHeight) {
  OrbitCamera c;
  c.set_home(home());
  c.set_lowest_eye(1.5);
  for (int k = 0; k < 200; ++k) {
    c.zoom(1);
    const lod::Camera v = c.camera(640, 360);
    ASSERT_GE(v.eye[1], 1.5) << "after " << k + 1 << " wheel steps";
    ASSERT_NE(v.eye, v.target);
  }
  c.orbit(0, -1000);  // as low as the pitch goes
  EXPECT_GE(c.camera(640, 360).eye[1], 1.5);
}

TEST(OrbitCamera, AnEyeAboveTheLowestHeightIsLeftOnItsOrbit) {
  OrbitCamera c;
  c.set_home(home());
  c.set_lowest_eye(1.5);
  const lod::Camera v = c.camera(640, 360);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(v.eye[k], home().eye[k], 1e-9);
}

}  // namespace
}  // namespace pond::app::demo
