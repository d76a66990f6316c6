#include "app/demo/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pond::app::demo {
namespace {

constexpr double kRadiansPerPixel = 0.005;
constexpr double kMaxPitch = 1.55;  // just short of straight down: the LOD's up (+y) stays defined
constexpr double kMinPitch = -0.2;  // a little below the water surface

}  // namespace

void OrbitCamera::set_home(const lod::Camera& camera) {
  home_ = camera;
  reset();
}

void OrbitCamera::reset() {
  target_ = home_.target;
  const double dx = home_.eye[0] - target_[0], dy = home_.eye[1] - target_[1], dz = home_.eye[2] - target_[2];
  distance_ = std::max(1e-3, std::sqrt(dx * dx + dy * dy + dz * dz));
  pitch_ = std::clamp(std::asin(std::clamp(dy / distance_, -1.0, 1.0)), kMinPitch, kMaxPitch);
  yaw_ = std::atan2(dx, dz);
  fovy_ = home_.fovy_degrees;
}

std::array<double, 3> OrbitCamera::eye() const {
  const double c = std::cos(pitch_);
  return {target_[0] + distance_ * c * std::sin(yaw_), std::max(lowest_eye_, target_[1] + distance_ * std::sin(pitch_)),
          target_[2] + distance_ * c * std::cos(yaw_)};
}

void OrbitCamera::orbit(double dx_px, double dy_px) {
  yaw_ -= dx_px * kRadiansPerPixel;
  pitch_ = std::clamp(pitch_ + dy_px * kRadiansPerPixel, kMinPitch, kMaxPitch);
}

void OrbitCamera::pan(double dx_px, double dy_px, int viewport_height) {
  // World units per pixel at the target's depth, so the point under the cursor stays under it.
  const double per_px = 2.0 * distance_ * std::tan(fovy_ * std::numbers::pi / 360.0) / std::max(1, viewport_height);
  const std::array<double, 3> right{std::cos(yaw_), 0, -std::sin(yaw_)};
  // Dragging up moves the target away along the ground direction of the view (stays on its height).
  const std::array<double, 3> ahead{-std::sin(yaw_), 0, -std::cos(yaw_)};
  for (int k = 0; k < 3; ++k) target_[k] += (-dx_px * right[k] + dy_px * ahead[k]) * per_px;
}

void OrbitCamera::zoom(double wheel_steps) {
  distance_ = std::clamp(distance_ * std::pow(0.9, wheel_steps), 0.5, 1e5);
}

lod::Camera OrbitCamera::camera(int width, int height) const {
  return lod::Camera{.eye = eye(), .target = target_, .fovy_degrees = fovy_, .width = width, .height = height};
}

}  // namespace pond::app::demo
