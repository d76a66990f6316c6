#include "view/frame_plan.h"

#include <algorithm>
#include <cmath>

namespace pond::view {

double nearest_caster_pixels(std::span<const ShadowCaster> casters, const std::array<float, 16>& view_proj, int height) {
  // By the box centre's clip w (the view depth) less its half diagonal; |m[5]| h / 2 pixels per
  // unit at depth 1.
  double pixels = 0.0;
  for (const ShadowCaster& c : casters) {
    double w = 0.0, reach = 0.0;
    for (int k = 0; k < 3; ++k) {
      w += view_proj[3 + 4 * k] * 0.5 * (c.lo[k] + c.hi[k]);
      reach += 0.25 * (c.hi[k] - c.lo[k]) * (c.hi[k] - c.lo[k]);
    }
    const double depth = std::max(w + view_proj[15] - std::sqrt(reach), 1e-2);
    pixels = std::max(pixels, std::abs(view_proj[5]) * 0.5 * height / depth);
  }
  return pixels;
}

FramePlan plan_frame(const PlanInput& in) {
  FramePlan plan;
  plan.caustics = in.effects.caustics;
  plan.reflection = in.effects.reflections;
  if (!in.effects.shadows) return plan;
  const double pixels = nearest_caster_pixels(in.casters, in.view_proj, in.height);
  const std::optional<SunShadowView> fitted =
      fit_sun_shadow(in.sun, in.casters, pixels * kShadowTexelsPerPixel, kMaxShadowMapSize);
  if (!fitted) return plan;
  std::vector<PixelRect> rects;
  for (const ShadowCaster& c : in.casters)
    if (const auto r = shadow_pixels(*fitted, c, in.view_proj, in.width, in.height, -in.floor_depth,
                                     in.land_height + kShadowWaveMargin))
      rects.push_back(*r);
  rects = merge_overlapping(rects);
  if (rects.empty()) return plan;
  plan.shadow = *fitted;
  plan.shadow_rects = std::move(rects);
  return plan;
}

}  // namespace pond::view
