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

// The scene's camera ("camera") at width x height, or, without one, a three-quarter view of the whole pond
// from its near (+z) side, slightly to the left, looking at its centre.
lod::Camera scene_camera(const std::optional<CameraSpec>& camera, const sim::WaterModel& model, int width, int height);

}  // namespace pond::view
