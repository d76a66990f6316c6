#pragma once
// The demo's camera: orbits a target point (yaw around world +y, pitch above the horizon) at a
// distance; pans the target in the view plane; zooms by scaling the distance. Produces the
// lod::Camera the frame loop and the LOD builder use (up is world +y).
#include <array>

#include "lod/camera_budget.h"

namespace pond::app::demo {

class OrbitCamera {
 public:
  // Takes eye, target and fovy from `camera` (e.g. FrameLoop::default_camera) as its home view.
  void set_home(const lod::Camera& camera);
  void reset();                     // back to the home view
  void orbit(double dx_px, double dy_px);  // drag in pixels: left/right yaw, up/down pitch
  void pan(double dx_px, double dy_px, int viewport_height);  // the target follows the cursor
  void zoom(double wheel_steps);    // positive = closer
  // The lowest the eye may go (world y): above the water and the land, so that zooming in or
  // orbiting low never takes the view under the surface. The eye is raised to it, its x and z kept.
  void set_lowest_eye(double y) { lowest_eye_ = y; }
  lod::Camera camera(int width, int height) const;

 private:
  std::array<double, 3> eye() const;
  std::array<double, 3> target_{0, 0, 0};
  double yaw_ = 0, pitch_ = 0.5, distance_ = 10, fovy_ = 45;
  double lowest_eye_ = -1e300;
  lod::Camera home_;
};

}  // namespace pond::app::demo
