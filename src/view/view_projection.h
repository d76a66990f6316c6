#pragma once
// The camera of a frame as matrices for the shaders, and the default camera of a scene. The same
// lod::Camera drives the LOD builder's pixel budgets, so what is drawn and what the LOD bounds
// agree: width/height are the target's, up is world +y.
#include <array>
#include <optional>

#include "lod/camera_budget.h"
#include "sim/model.h"
#include "view/view_spec.h"

namespace pond::view {

// World -> clip, column-major, Vulkan conventions (clip y down, depth 0..1), perspective with the
// camera's vertical field of view. near/far are chosen to hold the pond and its surroundings.
std::array<float, 16> view_projection(const lod::Camera& camera, const sim::WaterModel& model);

// `camera` as float view matrices and the LOD can use it, or InputError naming the option or key
// (`eye_name`, `target_name`: "--eye", "camera.eye"): every coordinate within kMaxCameraCoordinate
// and the target apart from the eye. A target so close to the eye that the squares of their
// difference vanish (a denormal away) is moved along the same direction to a distance the
// arithmetic resolves, so the view is that of the same direction at a sane scale; any other camera
// is returned as it is.
lod::Camera checked_camera(lod::Camera camera, const char* eye_name, const char* target_name);
// The coordinate check alone, for a point given before the rest of the camera is known.
void check_camera_point(const std::array<double, 3>& point, const char* name);

// The scene's camera ("camera") at width x height, or, without one, a three-quarter view of the whole pond
// from its near (+z) side, slightly to the left, looking at its centre.
lod::Camera scene_camera(const std::optional<CameraSpec>& camera, const sim::WaterModel& model, int width, int height);

}  // namespace pond::view
