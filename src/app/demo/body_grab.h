#pragma once
// The demo's hold on a body (issue 16): a left press on a sphere grabs it; while the button is
// down the body is dragged, kinematic, toward the point under the cursor on the horizontal plane
// at the height it was grabbed at (keeping the offset between that point and its centre at the
// press, so it does not jump), over the frame's steps; the wheel raises or lowers that plane; the
// release lets it go with the drag's velocity, vertical included (a floating body floats on with
// it, sim::Session::release_body).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "app/demo/picking.h"
#include "lod/camera_budget.h"
#include "sim/session.h"

namespace pond::app::demo {

class BodyGrab {
 public:
  // Grabs the nearest body `ray` meets: its index, or nothing when the ray meets none.
  std::optional<std::size_t> grab(sim::Session& session, const Ray& ray);
  bool active() const { return index_.has_value(); }
  std::size_t index() const { return *index_; }
  void move_cursor(double x, double y) { cursor_ = {x, y}; }
  // Raises (dy > 0) or lowers the plane the held body moves in by dy (world units): the wheel. The
  // plane stays between the pool's floor and a pond's extent above the land.
  void lift(double dy) { height_ += dy; }
  // Once a frame, before the frame's steps: the held body toward the point under the cursor, over
  // `steps` steps (0 = paused: it waits there, and the drag's velocity is kept).
  void drag(sim::Session& session, const lod::Camera& camera, std::int64_t steps);
  // Lets the body go with the drag's velocity (world units per unit of simulated time), returned.
  std::array<double, 3> release(sim::Session& session);
  // Body `removed` is gone: the held one's index follows, or the hold ends when it was that one.
  void body_removed(std::size_t removed);

 private:
  std::optional<std::size_t> index_;
  double height_ = 0;                    // of the plane the body moves in (world)
  std::array<double, 3> offset_{};       // its centre minus the plane's point under the press
  std::array<double, 2> cursor_{};       // pixels
  std::optional<std::array<double, 3>> last_target_;
  std::array<double, 3> velocity_{};     // smoothed over the last frames
};

}  // namespace pond::app::demo
