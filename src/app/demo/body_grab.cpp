#include "app/demo/body_grab.h"

#include <algorithm>
#include <vector>

namespace pond::app::demo {
namespace {

// The release velocity follows the drag of the last few frames: each frame's displacement over
// its simulated time, blended with this weight (a jittery last frame does not fling the ball).
constexpr double kVelocityBlend = 0.5;

}  // namespace

std::optional<std::size_t> BodyGrab::grab(sim::Session& session, const Ray& ray) {
  const std::vector<sim::BodyState> states = session.bodies();
  const auto& specs = session.water().bodies;
  const double h = session.model().spacing;
  std::vector<Sphere> spheres;
  for (std::size_t b = 0; b < states.size() && b < specs.size(); ++b)
    spheres.push_back({{states[b].x * h, states[b].y * h, states[b].z * h}, specs[b].radius});
  const std::optional<std::size_t> hit = pick_sphere(ray, spheres);
  if (!hit) return std::nullopt;
  const Sphere& s = spheres[*hit];
  const std::optional<std::array<double, 3>> under = intersect_height(ray, s.centre[1]);
  index_ = hit;
  height_ = s.centre[1];
  offset_ = under ? std::array<double, 3>{s.centre[0] - (*under)[0], 0.0, s.centre[2] - (*under)[2]}
                  : std::array<double, 3>{};
  last_target_ = s.centre;
  velocity_ = {};
  return hit;
}

void BodyGrab::drag(sim::Session& session, const lod::Camera& camera, std::int64_t steps) {
  if (!index_) return;
  // The wheel's plane stays between the pool's floor and a pond's extent above the land.
  const sim::WaterModel& m = session.model();
  height_ = std::clamp(height_, -m.basin.floor_depth, m.basin.land_height + double(std::max(m.rows, m.cols)) * m.spacing);
  const std::optional<std::array<double, 3>> under = intersect_height(pixel_ray(camera, cursor_[0], cursor_[1]), height_);
  const std::array<double, 3> target =
      under ? std::array<double, 3>{(*under)[0] + offset_[0], height_, (*under)[2] + offset_[2]}
            : std::array<double, 3>{(*last_target_)[0], height_, (*last_target_)[2]};
  if (steps > 0) {
    const double seconds = static_cast<double>(steps) * session.water().physics.dt;
    for (int k = 0; k < 3; ++k)
      velocity_[k] = (1 - kVelocityBlend) * velocity_[k] + kVelocityBlend * (target[k] - (*last_target_)[k]) / seconds;
  }
  last_target_ = target;
  session.drag_body(*index_, target, std::max<std::int64_t>(1, steps));
}

std::array<double, 3> BodyGrab::release(sim::Session& session) {
  if (!index_) return {};
  const std::array<double, 3> v = velocity_;
  session.release_body(*index_, v);
  index_.reset();
  return v;
}

void BodyGrab::body_removed(std::size_t removed) {
  if (!index_) return;
  if (*index_ == removed) index_.reset();
  else if (*index_ > removed) --*index_;
}

}  // namespace pond::app::demo
