#include "view/frame_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

std::optional<PixelRect> submerged_pixels(const ShadowCaster& box, const std::array<float, 16>& view_proj, int width,
                                          int height, double floor_depth) {
  // tan(asin(1 / 1.33)) = 1.14 per unit of depth, to the box's bottom or the floor.
  const double reach = 1.15 * std::min(-static_cast<double>(box.lo[1]), floor_depth) + kShadowWaveMargin;
  const std::array<float, 16>& m = view_proj;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (int k = 0; k < 8; ++k) {
    const double x = (k & 1 ? box.hi[0] + reach : box.lo[0] - reach), z = (k & 2 ? box.hi[2] + reach : box.lo[2] - reach);
    const double y = k & 4 ? kShadowWaveMargin : -kShadowWaveMargin;
    const double cx = m[0] * x + m[4] * y + m[8] * z + m[12], cy = m[1] * x + m[5] * y + m[9] * z + m[13];
    const double cw = m[3] * x + m[7] * y + m[11] * z + m[15];
    if (cw <= 1e-6) return PixelRect{0, 0, width, height};
    const double px = (cx / cw * 0.5 + 0.5) * width, py = (cy / cw * 0.5 + 0.5) * height;
    x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
  }
  return padded_pixels(x0, y0, x1, y1, width, height);
}

ShadowReceivers shadow_receivers(const PlanInput& in) {
  return {-in.floor_depth, -kShadowWaveMargin, in.land_height + kShadowWaveMargin};
}

FramePlan plan_frame(const PlanInput& in) {
  FramePlan plan;
  plan.caustics = in.effects.caustics;
  plan.reflection = in.effects.reflections;
  plan.effects = in.effects;
  std::vector<PixelRect> below, shadowed;
  if (in.effects.submerged) {
    auto add = [&](ShadowCaster box) {
      if (box.lo[1] >= 0.0f || box.hi[1] < -in.floor_depth) return;  // all above the water (a tree), or below the floor
      box.hi[1] = std::min(box.hi[1], 0.0f);
      if (auto r = submerged_pixels(box, in.view_proj, in.width, in.height, in.floor_depth)) {
        r->submerged = true;
        below.push_back(*r);
      }
    };
    for (const ShadowCaster& c : in.casters) add(c);
    for (const ShadowCaster& c : in.submerged) add(c);
    below = merge_overlapping(std::move(below));
    plan.submerged = !below.empty();
  }
  const double pixels = nearest_caster_pixels(in.casters, in.view_proj, in.height);
  const std::optional<SunShadowView> fitted =
      in.effects.shadows ? fit_sun_shadow(in.sun, in.casters, pixels * kShadowTexelsPerPixel, kMaxShadowMapSize)
                         : std::nullopt;
  if (fitted)
    for (const ShadowCaster& c : in.casters)
      if (auto r = shadow_pixels(*fitted, c, in.view_proj, in.width, in.height, shadow_receivers(in))) {
        r->shadowed = true;
        shadowed.push_back(*r);
      }
  shadowed = merge_overlapping(std::move(shadowed));
  if (!shadowed.empty()) plan.shadow = *fitted;
  // Where both can show, first (the main pass shades each pixel in the first rectangle that holds
  // it): the two kinds' overlaps, which do not overlap each other; then each kind's own.
  for (const PixelRect& s : shadowed)
    for (const PixelRect& u : below) {
      const PixelRect both{std::max(s.x0, u.x0), std::max(s.y0, u.y0), std::min(s.x1, u.x1), std::min(s.y1, u.y1), true, true};
      if (both.x0 < both.x1 && both.y0 < both.y1) plan.shadow_rects.push_back(both);
    }
  plan.shadow_rects.insert(plan.shadow_rects.end(), shadowed.begin(), shadowed.end());
  plan.shadow_rects.insert(plan.shadow_rects.end(), below.begin(), below.end());
  return plan;
}

}  // namespace pond::view
