#pragma once
// A frame's plan (no Vulkan): which of the passes before the main one it draws, and for the sun's
// shadow map its view, fitted to this frame's casters; and the parts of the target its shadows can
// reach or what lies under the water can show through it (where the land and the water are drawn
// with the shaders that sample the map and the submerged layer).
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "view/pixel_rect.h"
#include "view/sun_shadow.h"
#include "view/view_spec.h"

namespace pond::view {

// The sun's shadow map: texels per unit over the camera's pixels per unit at the nearest caster (a
// shadow on the ground is stretched along the sunlight, and the filter spans two texels), and its
// largest size. The receivers' heights the shadows are looked for between: the floor and the land's
// top plus this much for wave crests.
inline constexpr double kShadowTexelsPerPixel = 1.5;
inline constexpr std::uint32_t kMaxShadowMapSize = 1024;
inline constexpr double kShadowWaveMargin = 1.0;

struct FramePlan {
  Effects effects;  // those asked for; a pass that needs no more than its switch reads it here
  bool caustics = false;
  bool reflection = false;
  // Something lies under the surface besides the floor and the rim's walls (islands' walls,
  // bodies) where the camera can see it: the frame draws the submerged layer
  // (render/submerged_pass.h).
  bool submerged = false;
  std::optional<SunShadowView> shadow;  // shadows on, something casts, and a shadow is on screen
  // Where its shadows can fall and where what is under the water can show (PixelRect's flags; empty
  // without either): the effect pipelines' scissor rectangles, in the order the main pass draws
  // them, the first holding a pixel shading it: where both can show, then each kind's own
  // rectangles, merged within their kind (they overlap the other kind's).
  std::vector<PixelRect> shadow_rects;
};

// What the scene around the frame is: the pond's floor depth and land height (world units) and
// the direction toward the sun.
struct PlanInput {
  Effects effects;
  std::span<const ShadowCaster> casters;
  // Boxes of what lies under the water besides the casters' parts below y = 0 (the islands' walls).
  std::span<const ShadowCaster> submerged;
  const std::array<float, 16>& view_proj;  // the camera's, column-major, Vulkan clip space
  int width = 0, height = 0;               // the target's
  std::array<double, 3> sun{};
  double floor_depth = 0, land_height = 0;
};

FramePlan plan_frame(const PlanInput& in);

// Where the frame's shadows are received: the floor, the lowest trough, the land's top plus the
// highest crest.
ShadowReceivers shadow_receivers(const PlanInput& in);

// The pixels of the water's surface through which `box` (below y = 0) can be seen: the rays that
// reach it enter the water within depth * tan(48.8 degrees) (the critical angle, 1 / 1.33) of it
// horizontally, the depth of its bottom (or the floor's), so its box widened by that much, between
// the wave margin's heights; the whole view when that reaches behind the eye, nothing when it is
// off screen.
std::optional<PixelRect> submerged_pixels(const ShadowCaster& box, const std::array<float, 16>& view_proj, int width,
                                          int height, double floor_depth);

// The camera's pixels per world unit at the nearest point of any caster's box (0 without casters):
// the shadow map's resolution follows it.
double nearest_caster_pixels(std::span<const ShadowCaster> casters, const std::array<float, 16>& view_proj, int height);

}  // namespace pond::view
