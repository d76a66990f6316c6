#pragma once
// The water renderer's per-frame uniforms (shared/water_render.h WaterFrame) packed from what a
// frame is: the camera and its matrix, the lighting, the pond's shape, the state's layout and the
// sun's shadow map. No Vulkan: the frame loop copies the result into the frame's uniform buffer.
#include <array>
#include <cstdint>
#include <optional>

#include "lod/camera_budget.h"
#include "shared/water_render.h"
#include "sim/model.h"
#include "view/sun_shadow.h"
#include "view/view_spec.h"

namespace pond::view {

// How far the reflection shifts per unit of the surface normal's xz tilt, in screen widths and
// heights: ripples of a few degrees wobble it by a few pixels.
inline constexpr float kReflectionShift = 0.05f;

// What a frame's uniforms are made of. `camera` has the target's size; `lighting.sun` is this
// frame's (the session's); stride and pitch are the drawn state's (floats between its component
// arrays, nodes between its rows).
struct FrameUniformsInput {
  const sim::WaterModel& model;
  const LightingSpec& lighting;
  const lod::Camera& camera;
  const std::array<float, 16>& view_proj;
  std::uint32_t stride = 0, pitch = 0;
  const SunShadowView* shadow = nullptr;  // the frame's shadow map, if it has one
};

shared::water_render::WaterFrame frame_uniforms(const FrameUniformsInput& in);

}  // namespace pond::view
