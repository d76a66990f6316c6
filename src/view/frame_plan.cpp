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
  const double reach = 1.15 * floor_depth + kShadowWaveMargin;  // tan(asin(1 / 1.33)) = 1.14
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
  auto pixel = [](double v, int size) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(size))); };
  const PixelRect rect{pixel(std::floor(x0) - 2.0, width), pixel(std::floor(y0) - 2.0, height),
                       pixel(std::ceil(x1) + 2.0, width), pixel(std::ceil(y1) + 2.0, height)};
  if (rect.x0 >= rect.x1 || rect.y0 >= rect.y1) return std::nullopt;
  return rect;
}

FramePlan plan_frame(const PlanInput& in) {
  FramePlan plan;
  plan.caustics = in.effects.caustics;
  plan.reflection = in.effects.reflections;
  std::vector<PixelRect> rects;
  if (in.effects.submerged) {
    auto add = [&](ShadowCaster box) {
      if (box.lo[1] >= 0.0f || box.hi[1] < -in.floor_depth) return;  // all above the water (a tree), or below the floor
      box.hi[1] = std::min(box.hi[1], 0.0f);
      if (const auto r = submerged_pixels(box, in.view_proj, in.width, in.height, in.floor_depth)) rects.push_back(*r);
    };
    for (const ShadowCaster& c : in.casters) add(c);
    for (const ShadowCaster& c : in.submerged) add(c);
    plan.submerged = !rects.empty();
  }
  const double pixels = nearest_caster_pixels(in.casters, in.view_proj, in.height);
  const std::optional<SunShadowView> fitted =
      in.effects.shadows ? fit_sun_shadow(in.sun, in.casters, pixels * kShadowTexelsPerPixel, kMaxShadowMapSize)
                         : std::nullopt;
  const std::size_t below = rects.size();
  if (fitted)
    for (const ShadowCaster& c : in.casters)
      if (const auto r = shadow_pixels(*fitted, c, in.view_proj, in.width, in.height, -in.floor_depth,
                                       in.land_height + kShadowWaveMargin))
        rects.push_back(*r);
  if (rects.size() > below) plan.shadow = *fitted;
  plan.shadow_rects = merge_overlapping(std::move(rects));
  return plan;
}

}  // namespace pond::view
