#include "view/sun_shadow.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pond::view {
namespace {

using V3 = std::array<double, 3>;

double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The box's corners.
std::array<V3, 8> corners(const ShadowCaster& c) {
  std::array<V3, 8> out;
  for (int k = 0; k < 8; ++k)
    out[k] = {(k & 1) ? c.hi[0] : c.lo[0], (k & 2) ? c.hi[1] : c.lo[1], (k & 4) ? c.hi[2] : c.lo[2]};
  return out;
}

}  // namespace

std::array<double, 3> unit(const std::array<double, 3>& d) {
  const double l = std::sqrt(dot(d, d));
  return {d[0] / l, d[1] / l, d[2] / l};
}

ShadowCaster sphere_caster(const std::array<float, 3>& centre, float radius) {
  return {{centre[0] - radius, centre[1] - radius, centre[2] - radius},
          {centre[0] + radius, centre[1] + radius, centre[2] + radius}};
}

std::optional<SunShadowView> fit_sun_shadow(const std::array<double, 3>& toward_sun,
                                            std::span<const ShadowCaster> casters, double texels_per_unit,
                                            std::uint32_t max_size) {
  if (casters.empty()) return std::nullopt;
  SunShadowView v;
  const V3 sun = unit(toward_sun);
  v.along = {-sun[0], -sun[1], -sun[2]};  // the sunlight's direction: depth grows along it
  // Across the light: any axis not parallel to it (the sun straight overhead takes x).
  v.right = unit(std::abs(sun[1]) > 0.999 ? cross(v.along, V3{0, 0, 1}) : cross(v.along, V3{0, 1, 0}));
  v.down = cross(v.along, v.right);  // right x down = along: right-handed like Vulkan's clip space
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::numeric_limits<double>::infinity();
    hi[k] = -lo[k];
  }
  for (const ShadowCaster& c : casters)
    for (const V3& p : corners(c)) {
      const double q[3] = {dot(p, v.right), dot(p, v.down), dot(p, v.along)};
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], q[k]);
        hi[k] = std::max(hi[k], q[k]);
      }
    }
  // Half the square's side, rounded up to a step of 2^(1/8) (two texels of margin), its size the
  // power of two nearest the texels wanted across it, and its centre on whole texels: a caster's
  // sway moves the grid only when the extent changes step.
  const double needed = 0.5 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
  v.half = std::exp2(std::ceil(std::log2(std::max(needed, 1e-3)) * 8.0) / 8.0);
  const double wanted = std::clamp(2.0 * v.half * texels_per_unit, 1.0, static_cast<double>(max_size));
  v.size = std::clamp<std::uint32_t>(1u << static_cast<int>(std::round(std::log2(wanted))), kMinShadowMapSize,
                                     std::max(max_size, kMinShadowMapSize));
  v.half *= 1.0 + 4.0 / v.size;
  const double texel = 2.0 * v.half / v.size;
  v.centre_right = std::round(0.5 * (lo[0] + hi[0]) / texel) * texel;
  v.centre_down = std::round(0.5 * (lo[1] + hi[1]) / texel) * texel;
  const double margin = 1e-3 * (hi[2] - lo[2]) + 1e-3;  // the casters' extreme points stay inside
  const double near = lo[2] - margin, range = hi[2] - lo[2] + 2.0 * margin;
  v.texels_per_unit = static_cast<float>(1.0 / texel);
  // Rows of the clip matrix, stored column-major.
  const double h = v.half;
  const double rows[3][4] = {{v.right[0] / h, v.right[1] / h, v.right[2] / h, -v.centre_right / h},
                             {v.down[0] / h, v.down[1] / h, v.down[2] / h, -v.centre_down / h},
                             {v.along[0] / range, v.along[1] / range, v.along[2] / range, -near / range}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) {
      v.clip[c * 4 + r] = static_cast<float>(rows[r][c]);
      // Texture coordinates: u, v = clip * 0.5 + 0.5 (Vulkan's viewport: row 0 at clip y = -1).
      v.texture[c * 4 + r] = static_cast<float>(r < 2 ? 0.5 * rows[r][c] + (c == 3 ? 0.5 : 0.0) : rows[r][c]);
    }
  v.clip[15] = v.texture[15] = 1.0f;
  return v;
}

std::optional<PixelRect> shadow_pixels(const SunShadowView& view, const ShadowCaster& caster,
                                       const std::array<float, 16>& view_proj, int width, int height,
                                       const ShadowReceivers& receivers) {
  const PixelRect all{0, 0, width, height};
  if (view.along[1] > -1e-3) return all;  // sunlight along the ground: shadows reach anywhere
  const std::array<float, 16>& m = view_proj;
  const std::array<float, 3> in_water = sunlight_in_water({-view.along[0], -view.along[1], -view.along[2]});
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  bool behind = false;
  // A receiver point and the point straight above it at the top (a floor point seen through the
  // water shows between itself and the surface point above it).
  auto add = [&](const V3& p) {
    for (double y : {p[1], receivers.top}) {
      const double cx = m[0] * p[0] + m[4] * y + m[8] * p[2] + m[12];
      const double cy = m[1] * p[0] + m[5] * y + m[9] * p[2] + m[13];
      const double cw = m[3] * p[0] + m[7] * y + m[11] * p[2] + m[15];
      if (cw <= 1e-6) behind = true;
      const double px = (cx / cw * 0.5 + 0.5) * width, py = (cy / cw * 0.5 + 0.5) * height;
      x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
    }
  };
  auto along = [&](const V3& a, const V3& d, double t) { return V3{a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]}; };
  const V3 light{view.along[0], view.along[1], view.along[2]};
  const V3 water{in_water[0], in_water[1], in_water[2]};
  for (const V3& a : corners(caster)) {
    if (a[1] < receivers.floor) continue;  // the corner is below every receiver
    // In the air: each corner's line away from the sun, p(t) = a + t along, t >= 0, between the
    // top and the lowest wave.
    const double t_top = std::max((receivers.top - a[1]) / light[1], 0.0);
    const double t_low = std::max((receivers.air_low - a[1]) / light[1], 0.0);
    add(along(a, light, t_top));
    add(along(a, light, t_low));
    // Under the water: from where that line meets the rest plane, down the refracted sunlight to
    // the floor (as water.frag traces it back up to its entry).
    if (receivers.floor < 0.0 && a[1] >= 0.0) {
      const V3 entry = along(a, light, a[1] / -light[1]);
      add(entry);
      add(along(entry, water, receivers.floor / water[1]));
    }
  }
  if (behind) return all;
  return padded_pixels(x0, y0, x1, y1, width, height);
}

std::vector<PixelRect> merge_overlapping(std::vector<PixelRect> rects) {
  auto overlap = [](const PixelRect& a, const PixelRect& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
  };
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t i = 0; i < rects.size() && !merged; ++i)
      for (std::size_t j = i + 1; j < rects.size() && !merged; ++j)
        if (overlap(rects[i], rects[j])) {
          rects[i] = {std::min(rects[i].x0, rects[j].x0), std::min(rects[i].y0, rects[j].y0),
                      std::max(rects[i].x1, rects[j].x1), std::max(rects[i].y1, rects[j].y1),
                      rects[i].shadowed || rects[j].shadowed, rects[i].submerged || rects[j].submerged};
          rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(j));
          merged = true;
        }
  }
  return rects;
}

std::array<float, 3> sunlight_in_water(const std::array<double, 3>& toward_sun) {
  const V3 sun = unit(toward_sun);
  constexpr double eta = 1.0 / 1.33;
  // GLSL's refract(I = -sun, N = +y, eta); k > 0 always for air to water.
  const double cos_i = std::max(sun[1], 0.0);
  const double k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
  const V3 t = unit({-eta * sun[0], -std::sqrt(k), -eta * sun[2]});
  return {static_cast<float>(t[0]), static_cast<float>(t[1]), static_cast<float>(t[2])};
}

}  // namespace pond::view
