#include "view/view_projection.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.h"
#include "core/text.h"

#define GLM_FORCE_DEPTH_ZERO_TO_ONE
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace pond::view {
namespace {

glm::dvec3 vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

}  // namespace

std::array<float, 16> view_projection(const lod::Camera& camera, const sim::WaterModel& model) {
  const glm::dvec3 eye = vec(camera.eye), target = vec(camera.target);
  const glm::dvec3 forward = glm::normalize(target - eye);
  // Up is +y; looking (almost) straight down or up, roll is undefined: take +z's opposite instead.
  const glm::dvec3 up = std::abs(forward.y) > 0.999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
  const glm::dmat4 view = glm::lookAtRH(eye, target, up);
  // Depth range: the pond spans S; the land around it reaches 4 S out (land_mesh.h).
  const double h = model.spacing;
  const double size = std::max(model.rows, model.cols) * h;
  const glm::dvec3 centre((model.cols - 1) * h * 0.5, 0.0, (model.rows - 1) * h * 0.5);
  const double far_plane = glm::length(eye - centre) + 6.0 * size;
  const double near_plane = std::max(far_plane * 2e-5, std::min(0.05 * h, std::max(1e-3, std::abs(eye.y) * 0.5)));
  glm::dmat4 proj = glm::perspectiveRH_ZO(glm::radians(camera.fovy_degrees),
                                          static_cast<double>(camera.width) / camera.height, near_plane, far_plane);
  proj[1][1] = -proj[1][1];  // Vulkan clip space: y points down
  const glm::mat4 vp = glm::mat4(proj * view);
  std::array<float, 16> out{};
  std::copy_n(glm::value_ptr(vp), 16, out.begin());
  return out;
}

void check_camera_point(const std::array<double, 3>& point, const char* name) {
  for (double x : point)
    if (!(std::fabs(x) <= kMaxCameraCoordinate))
      throw InputError(std::string(name) + " has a coordinate " + number_text(x) + ", outside [-" +
                       number_text(kMaxCameraCoordinate) + ", " + number_text(kMaxCameraCoordinate) +
                       "] (float view matrices)");
}

lod::Camera checked_camera(lod::Camera c, const char* eye_name, const char* target_name) {
  check_camera_point(c.eye, eye_name);
  check_camera_point(c.target, target_name);
  std::array<double, 3> d{};
  double largest = 0, eye_largest = 1;
  for (int k = 0; k < 3; ++k) {
    d[k] = c.target[k] - c.eye[k];
    largest = std::max(largest, std::fabs(d[k]));
    eye_largest = std::max(eye_largest, std::fabs(c.eye[k]));
  }
  if (largest == 0) throw InputError(std::string(target_name) + " must differ from " + eye_name);
  if (largest >= 0x1p-500) return c;  // the squares of the difference are normal doubles
  // The unit direction, found from the difference scaled to a largest component of 1 (exact for
  // the component that is largest), placed as far from the eye as its coordinates are large.
  double length2 = 0;
  for (double& x : d) x /= largest, length2 += x * x;
  const double reach = eye_largest / std::sqrt(length2);
  for (int k = 0; k < 3; ++k) c.target[k] = c.eye[k] + d[k] * reach;
  return c;
}

lod::Camera scene_camera(const std::optional<CameraSpec>& camera, const sim::WaterModel& model, int width, int height) {
  lod::Camera c;
  c.width = width;
  c.height = height;
  if (camera) {
    c.eye = camera->eye;
    c.target = camera->target;
    c.fovy_degrees = camera->fovy_degrees;
    return c;
  }
  const double h = model.spacing;
  const double w = (model.cols - 1) * h, d = (model.rows - 1) * h, size = std::max(w, d);
  c.eye = {w * 0.42, size * 0.3, d + size * 0.3};
  c.target = {w * 0.5, -size * 0.06, d * 0.4};
  c.fovy_degrees = 45.0;
  return c;
}

}  // namespace pond::view
