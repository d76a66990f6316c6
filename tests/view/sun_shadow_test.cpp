// The sun shadow map's view (view/sun_shadow.h): every caster lies inside the map and its depth
// range, depth grows along the sunlight, the fit is tight and sized to the texels asked for,
// stable under a small sway; the screen rectangles hold the shadows and merge; the sunlight under
// the water bends toward the vertical as Snell says.
#include "view/sun_shadow.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lod/camera_budget.h"
#include "sim/model.h"
#include "view/view_projection.h"

namespace pond::view {
namespace {

std::array<double, 3> apply(const std::array<float, 16>& m, double x, double y, double z) {
  return {m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13],
          m[2] * x + m[6] * y + m[10] * z + m[14]};
}

constexpr std::array<double, 3> kSun{-0.3, 0.38, -0.87};

TEST(SunShadow, NoCastersNoMap) { EXPECT_FALSE(fit_sun_shadow(kSun, {}, 4.0, 1024).has_value()); }

TEST(SunShadow, CastersFitInsideTheMapAndItsDepthRange) {
  const std::vector<ShadowCaster> casters{sphere_caster({160, 8, 128}, 8), {{38, -2, 198}, {42, 3, 202}}};
  const auto v = fit_sun_shadow(kSun, casters, 4.0, 1024);
  ASSERT_TRUE(v.has_value());
  for (const ShadowCaster& c : casters)
    for (int corner = 0; corner < 8; ++corner) {
      const double x = corner & 1 ? c.hi[0] : c.lo[0], y = corner & 2 ? c.hi[1] : c.lo[1],
                   z = corner & 4 ? c.hi[2] : c.lo[2];
      const auto t = apply(v->texture, x, y, z);
      for (int k = 0; k < 3; ++k) {
        EXPECT_GT(t[k], 0.0) << "corner " << corner << " coordinate " << k;
        EXPECT_LT(t[k], 1.0) << "corner " << corner << " coordinate " << k;
      }
    }
  // Clip is the texture's x, y times 2 minus 1.
  const auto c = apply(v->clip, 160, 8, 128), t = apply(v->texture, 160, 8, 128);
  EXPECT_NEAR(c[0], 2 * t[0] - 1, 1e-5);
  EXPECT_NEAR(c[1], 2 * t[1] - 1, 1e-5);
  EXPECT_NEAR(c[2], t[2], 1e-6);
}

TEST(SunShadow, DepthGrowsAlongTheSunlightAndTheFitIsTight) {
  const std::vector<ShadowCaster> one{sphere_caster({100, 7, 100}, 7)};
  const auto v = fit_sun_shadow(kSun, one, 1e6, 512);  // as fine as 512 texels allow
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->size, 512u);
  const double l = std::sqrt(kSun[0] * kSun[0] + kSun[1] * kSun[1] + kSun[2] * kSun[2]);
  const auto a = apply(v->texture, 100, 7, 100);
  const auto b = apply(v->texture, 100 + kSun[0] / l, 7 + kSun[1] / l, 100 + kSun[2] / l);  // a unit toward the sun
  EXPECT_LT(b[2], a[2]);
  EXPECT_NEAR(a[0], b[0], 1e-5);  // the same texel: along the sunlight
  EXPECT_NEAR(a[1], b[1], 1e-5);
  // The box's projection across the sunlight is at most its diagonal (14 sqrt 3) wide; the map is
  // at most 2^(1/8) (the rounding step) and a few texels wider than what it must hold.
  const double side = static_cast<double>(v->size) / v->texels_per_unit;
  EXPECT_LE(side, 14.0 * std::sqrt(3.0) * std::exp2(1.0 / 8.0) * (1.0 + 8.0 / 512));
  EXPECT_GE(side, 14.0);
}

TEST(SunShadow, SizeFollowsTheTexelsAskedFor) {
  const std::vector<ShadowCaster> one{sphere_caster({100, 7, 100}, 7)};
  const auto coarse = fit_sun_shadow(kSun, one, 4.0, 1024), fine = fit_sun_shadow(kSun, one, 16.0, 1024);
  ASSERT_TRUE(coarse && fine);
  EXPECT_EQ(fine->size, 4 * coarse->size);  // powers of two
  EXPECT_NEAR(fine->texels_per_unit / 16.0, 1.0, 0.5);
  EXPECT_EQ(fit_sun_shadow(kSun, one, 1e-6, 1024)->size, kMinShadowMapSize);
  EXPECT_EQ(fit_sun_shadow(kSun, one, 1e6, 1024)->size, 1024u);
}

TEST(SunShadow, ASmallSwayKeepsTheTexelGrid) {
  const auto a = fit_sun_shadow(kSun, std::vector<ShadowCaster>{sphere_caster({100, 7, 100}, 7)}, 1e6, 1024);
  const auto b = fit_sun_shadow(kSun, std::vector<ShadowCaster>{sphere_caster({100.013f, 7, 100.007f}, 7.002f)}, 1e6, 1024);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->texels_per_unit, b->texels_per_unit);
  // A fixed world point lands on the same position in both maps, up to whole texels.
  const auto pa = apply(a->texture, 95, 1, 103), pb = apply(b->texture, 95, 1, 103);
  for (int k = 0; k < 2; ++k) {
    const double texels = (pa[k] - pb[k]) * 1024;
    EXPECT_NEAR(texels, std::round(texels), 2e-2) << k;
  }
}

TEST(SunShadow, SunOverheadStillFits) {
  const auto v = fit_sun_shadow({0, 1, 0}, std::vector<ShadowCaster>{sphere_caster({5, 5, 5}, 1)}, 10.0, 256);
  ASSERT_TRUE(v.has_value());
  const auto top = apply(v->texture, 5, 6, 5), bottom = apply(v->texture, 5, 4, 5);
  EXPECT_LT(top[2], bottom[2]);
}

// A camera over a 101 x 101 pond looking at its middle, 640 x 360.
std::array<float, 16> camera_over_pond() {
  sim::WaterModel model;
  model.rows = model.cols = 101;
  lod::Camera c;
  c.eye = {50, 60, 110};
  c.target = {50, 0, 50};
  c.fovy_degrees = 50;
  c.width = 640;
  c.height = 360;
  return view_projection(c, model);
}

std::array<double, 2> pixel(const std::array<float, 16>& m, double x, double y, double z) {
  const double cx = m[0] * x + m[4] * y + m[8] * z + m[12], cy = m[1] * x + m[5] * y + m[9] * z + m[13];
  const double cw = m[3] * x + m[7] * y + m[11] * z + m[15];
  return {(cx / cw * 0.5 + 0.5) * 640, (cy / cw * 0.5 + 0.5) * 360};
}

// The floor 3 below the rest plane, waves 1 deep, land and crests up to 2.
constexpr ShadowReceivers kReceivers{-3.0, -1.0, 2.0};

bool inside(const PixelRect& r, std::array<double, 2> p) { return p[0] >= r.x0 && p[0] < r.x1 && p[1] >= r.y0 && p[1] < r.y1; }

TEST(SunShadow, ScreenRectangleHoldsTheShadowAndNotTheSunSide) {
  const std::array<float, 16> vp = camera_over_pond();
  const ShadowCaster pole{{49.8f, 1.0f, 49.8f}, {50.2f, 9.0f, 50.2f}};  // a pole on an island 1 high
  const auto v = fit_sun_shadow(kSun, std::vector<ShadowCaster>{pole}, 4.0, 1024);
  ASSERT_TRUE(v.has_value());
  const auto r = shadow_pixels(*v, pole, vp, 640, 360, kReceivers);
  ASSERT_TRUE(r.has_value());
  const auto step = std::array<double, 2>{-kSun[0] / kSun[1], -kSun[2] / kSun[1]};
  // Its shadow on the island (y = 1), on the water (y = 0) and, down the refracted sunlight from
  // there, the floor (y = -3).
  const std::array<float, 3> t = sunlight_in_water(kSun);
  const double run = 3.0 / -t[1];
  for (double h = 0.0; h <= 8.0; h += 1.0) {
    EXPECT_TRUE(inside(*r, pixel(vp, 50 + step[0] * h, 1.0, 50 + step[1] * h))) << h;
    EXPECT_TRUE(inside(*r, pixel(vp, 50 + step[0] * (h + 1), 0.0, 50 + step[1] * (h + 1)))) << h;
    EXPECT_TRUE(inside(*r, pixel(vp, 50 + step[0] * (h + 1) + t[0] * run, -3.0, 50 + step[1] * (h + 1) + t[2] * run)))
        << h;
  }
  // Nothing toward the sun: a point 3 units that way is outside.
  EXPECT_FALSE(inside(*r, pixel(vp, 50 - step[0] * 3, 1.0, 50 - step[1] * 3)));
  // A box wholly below the floor casts nowhere; one behind the eye makes it the whole view.
  EXPECT_FALSE(shadow_pixels(*v, {{40, -9, 40}, {41, -8, 41}}, vp, 640, 360, kReceivers).has_value());
  const auto all = shadow_pixels(*v, {{49, 1, 108}, {51, 80, 112}}, vp, 640, 360, kReceivers);
  ASSERT_TRUE(all.has_value());
  EXPECT_EQ(all->x0, 0);
  EXPECT_EQ(all->x1, 640);
}

// A caster just in front of the eye projects billions of pixels away: the rectangle is clamped
// to the view before it becomes ints (UBSan's float-cast-overflow would stop the old cast).
TEST(SunShadow, APointJustInFrontOfTheEyeStaysInTheView) {
  const ShadowCaster box{{49.8f, 1.0f, 49.8f}, {50.2f, 9.0f, 50.2f}};
  const auto v = fit_sun_shadow(kSun, std::vector<ShadowCaster>{box}, 4.0, 1024);
  ASSERT_TRUE(v.has_value());
  for (const float sx : {1e4f, -1e4f}) {
    std::array<float, 16> vp{};  // clip x = sx * world x, clip y = world y, clip w = 2e-6
    vp[0] = sx;
    vp[5] = 1.0f;
    vp[15] = 2e-6f;
    const auto r = shadow_pixels(*v, box, vp, 640, 360, kReceivers);
    if (r) {
      EXPECT_GE(r->x0, 0);
      EXPECT_LE(r->x1, 640);
      EXPECT_GE(r->y0, 0);
      EXPECT_LE(r->y1, 360);
    }
    EXPECT_FALSE(r.has_value()) << sx;  // wholly off one side of the view
  }
}

TEST(SunShadow, OverlappingRectanglesMerge) {
  const auto m = merge_overlapping({{0, 0, 10, 10}, {5, 5, 20, 20}, {30, 30, 40, 40}, {19, 0, 31, 2}});
  // The first two overlap; their union then overlaps the fourth, which overlaps nothing else first.
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].x0, 0);
  EXPECT_EQ(m[0].x1, 31);
  EXPECT_EQ(m[0].y1, 20);
  EXPECT_EQ(m[1].x0, 30);
  EXPECT_TRUE(merge_overlapping({{0, 0, 10, 10}, {10, 0, 20, 10}}).size() == 2u);  // touching only
}

TEST(SunShadow, SunlightUnderWaterBendsTowardTheVertical) {
  const std::array<float, 3> t = sunlight_in_water(kSun);
  const double l = std::sqrt(kSun[0] * kSun[0] + kSun[1] * kSun[1] + kSun[2] * kSun[2]);
  EXPECT_NEAR(t[0] * t[0] + t[1] * t[1] + t[2] * t[2], 1.0, 1e-6);
  EXPECT_LT(t[1], -kSun[1] / l);  // steeper than in air
  // Snell: sin in the water = sin in the air / 1.33.
  const double sin_air = std::sqrt(kSun[0] * kSun[0] + kSun[2] * kSun[2]) / l;
  EXPECT_NEAR(std::sqrt(t[0] * t[0] + t[2] * t[2]), sin_air / 1.33, 1e-6);
  const std::array<float, 3> down = sunlight_in_water({0, 2, 0});
  EXPECT_NEAR(down[1], -1.0f, 1e-6);
}

}  // namespace
}  // namespace pond::view
