#pragma once
// The sun's shadow map's view (no Vulkan): an orthographic projection along the sunlight fitted to
// the casters' bounding spheres (the trees, the bodies), so the map's texels are spent on them
// alone; where on screen their shadows can fall; and the sunlight's direction under the water.
// render/shadow_pass.h draws the map with it, the land and the water shaders sample it
// (shared/shadow_sampling.h).
//
// Light space: x to the right of the sunlight, y "down" across it (so x, y, depth is right-handed,
// as the camera's Vulkan clip space, and front faces keep their winding), depth along the sunlight
// (0 at the casters' point nearest the sun, 1 at their farthest). The map's extent is rounded up to
// a step of 2^(1/8) and its centre snapped to whole texels, so a swaying tree moves its shadow by
// whole texels instead of resampling its edges every frame (shimmer). Its size (texels a side) is
// a power of two that gives the casters about as many texels per unit as the camera gives them
// pixels: finer would cost the shadow pass without showing.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "view/pixel_rect.h"

namespace pond::view {

// A caster's bounding box (world units, lo <= hi).
struct ShadowCaster {
  std::array<float, 3> lo{}, hi{};
};

// The box around a sphere.
ShadowCaster sphere_caster(const std::array<float, 3>& centre, float radius);

struct SunShadowView {
  std::array<float, 16> clip{};     // world -> Vulkan clip of the map (column-major; w = 1)
  std::array<float, 16> texture{};  // world -> (u, v, depth): u, v in [0, 1] across the map
  std::uint32_t size = 0;           // texels a side
  float texels_per_unit = 0.0f;     // map texels per world unit across the sunlight
  // Light space: unit axes (world) and the map's square, centre +- half along right and down.
  std::array<double, 3> right{}, down{}, along{};
  double centre_right = 0.0, centre_down = 0.0, half = 0.0;
};

inline constexpr std::uint32_t kMinShadowMapSize = 64;

// The view of a map covering `casters` with about `texels_per_unit` texels per world unit (its size
// a power of two in [kMinShadowMapSize, max_size]), or nothing when there are none.
// `toward_sun`: the direction toward the sun (any length but zero).
std::optional<SunShadowView> fit_sun_shadow(const std::array<double, 3>& toward_sun,
                                            std::span<const ShadowCaster> casters, double texels_per_unit,
                                            std::uint32_t max_size);

// The heights a shadow is received between (world y): in the air, along the sunlight, from the
// lowest wave trough `air_low` to `top` (the land's top and the highest crest); under the water,
// from the rest plane y = 0 down the refracted sunlight to the pool's `floor` (the floor and the
// walls seen through the water, lit where their sunlight entered: water.frag).
struct ShadowReceivers {
  double floor = 0, air_low = 0, top = 0;
};

// The pixels of a width x height view (`view_proj`: column-major, Vulkan clip space) where
// `caster`'s shadow can show on `receivers`: the bounding box of what its box's corners sweep along
// the sunlight (away from the sun only) in the air and, from where that meets y = 0, along the
// refracted sunlight under the water, each point also lifted to the top (a floor point seen
// through the water shows between itself and the surface point above it); the whole view when
// that reaches behind the eye; nothing when it is off screen or the box lies below the floor.
std::optional<PixelRect> shadow_pixels(const SunShadowView& view, const ShadowCaster& caster,
                                       const std::array<float, 16>& view_proj, int width, int height,
                                       const ShadowReceivers& receivers);

// The rectangles, with every two that overlap replaced by their bounding box (and the union of
// what they are for) until none overlap (fewer draws).
std::vector<PixelRect> merge_overlapping(std::vector<PixelRect> rects);

// The direction sunlight travels under the water (refracted at the flat rest surface, air to water,
// 1 / 1.33): unit, pointing down.
std::array<float, 3> sunlight_in_water(const std::array<double, 3>& toward_sun);

// `d` scaled to unit length (the sun's direction as the shaders take it).
std::array<double, 3> unit(const std::array<double, 3>& d);

}  // namespace pond::view
