// A frame's plan and uniforms without Vulkan (view/frame_plan.h, view/frame_uniforms.h,
// view/caustics_grid.h): the passes follow the effects, the shadow map only when something casts a
// shadow that can be seen, its rectangles hold the casters' shadows; the uniforms carry the camera,
// the light, the pond and the state's layout where the shaders read them; the caustics map and its
// rays fit their limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "scene/scene.h"
#include "sim/model.h"
#include "view/caustics_grid.h"
#include "view/frame_plan.h"
#include "view/frame_uniforms.h"
#include "view/view_projection.h"

namespace pond::view {
namespace {

struct Frame {
  scene::Scene scene = scene::load_scene("");
  sim::WaterModel model = sim::build_model(scene);
  lod::Camera camera = scene_camera(scene.camera, model, 640, 400);
  std::array<float, 16> view_proj = view_projection(camera, model);

  FramePlan plan(const Effects& effects, const std::vector<ShadowCaster>& casters) const {
    return plan_frame({effects, casters, {}, view_proj, camera.width, camera.height, scene.lighting.sun,
                       scene.basin.floor_depth, scene.basin.land_height});
  }
};

TEST(FramePlan, PassesFollowTheEffects) {
  const Frame f;
  const std::vector<ShadowCaster> ball{sphere_caster({25, 1, 25}, 2)};
  const FramePlan all = f.plan({}, ball);
  EXPECT_TRUE(all.caustics && all.reflection && all.shadow.has_value());
  EXPECT_TRUE(all.submerged);  // the ball's lower half
  const FramePlan none = f.plan({.reflections = false, .caustics = false, .shadows = false, .submerged = false}, ball);
  EXPECT_FALSE(none.caustics || none.reflection || none.shadow.has_value() || none.submerged);
  EXPECT_TRUE(none.shadow_rects.empty());
}

TEST(FramePlan, NoShadowMapWithoutCastersOrWhenTheirShadowsAreOffScreen) {
  const Frame f;
  EXPECT_FALSE(f.plan({}, {}).shadow.has_value());
  // Far behind the camera's back and below the floor: nothing of its shadow can show.
  const FramePlan away = f.plan({}, {sphere_caster({25, -500, 5000}, 1)});
  EXPECT_FALSE(away.shadow.has_value());
  EXPECT_TRUE(away.shadow_rects.empty());
}

// (Rectangles of one kind do not overlap; where shadows and what is under the water meet, the
// overlap comes first with both flags.)
TEST(FramePlan, ShadowRectanglesHoldTheCastersShadowAndDoNotOverlap) {
  const Frame f;
  const std::vector<ShadowCaster> casters{sphere_caster({20, 1, 25}, 2), sphere_caster({21, 1, 26}, 2),
                                          sphere_caster({40, 1, 10}, 1.5)};
  const FramePlan p = f.plan({}, casters);
  ASSERT_TRUE(p.shadow.has_value());
  ASSERT_FALSE(p.shadow_rects.empty());
  // Each caster's own rectangle lies inside a merged one.
  for (const ShadowCaster& c : casters) {
    const ShadowReceivers receivers{-f.scene.basin.floor_depth, -kShadowWaveMargin,
                                    f.scene.basin.land_height + kShadowWaveMargin};
    const auto r = shadow_pixels(*p.shadow, c, f.view_proj, f.camera.width, f.camera.height, receivers);
    ASSERT_TRUE(r.has_value());
    bool held = false;
    for (const PixelRect& m : p.shadow_rects)
      held = held || (m.shadowed && m.x0 <= r->x0 && m.y0 <= r->y0 && r->x1 <= m.x1 && r->y1 <= m.y1);
    EXPECT_TRUE(held);
  }
  for (std::size_t a = 0; a < p.shadow_rects.size(); ++a)
    for (std::size_t b = a + 1; b < p.shadow_rects.size(); ++b) {
      const PixelRect &r = p.shadow_rects[a], &s = p.shadow_rects[b];
      if (r.shadowed != s.shadowed || r.submerged != s.submerged) continue;  // the kinds overlap each other
      EXPECT_TRUE(r.x1 <= s.x0 || s.x1 <= r.x0 || r.y1 <= s.y0 || s.y1 <= r.y0) << a << " and " << b << " overlap";
    }
}

// What lies under the water shows through the surface above it and beside it (as far as a ray can
// bend, 1.15 times the depth of its bottom): the rectangles hold the surface around a sunk ball; nothing above the water or
// below the floor asks for them.
TEST(FramePlan, SubmergedRectanglesHoldTheSurfaceThroughWhichItShows) {
  const Frame f;
  const Effects no_shadows{.shadows = false};
  const FramePlan sunk = f.plan(no_shadows, {sphere_caster({25, -1.5f, 25}, 1)});
  ASSERT_TRUE(sunk.submerged);
  ASSERT_FALSE(sunk.shadow.has_value());
  const double reach = 1.1 * std::min(2.5, f.scene.basin.floor_depth);  // the ball's bottom is 2.5 down
  for (const auto& [x, z] : std::vector<std::array<double, 2>>{{25, 25}, {26 + reach, 25}, {24 - reach, 26}, {25, 26 + reach}}) {
    const std::array<float, 16>& m = f.view_proj;  // the surface point (x, 0, z) on screen
    const double w = m[3] * x + m[11] * z + m[15];
    const int u = static_cast<int>((m[0] * x + m[8] * z + m[12]) / w * 0.5 * f.camera.width + 0.5 * f.camera.width);
    const int v = static_cast<int>((m[1] * x + m[9] * z + m[13]) / w * 0.5 * f.camera.height + 0.5 * f.camera.height);
    bool held = false;
    for (const PixelRect& r : sunk.shadow_rects) held = held || (r.x0 <= u && u < r.x1 && r.y0 <= v && v < r.y1);
    EXPECT_TRUE(held) << "the surface at " << x << ", " << z;
  }
  EXPECT_FALSE(f.plan(no_shadows, {sphere_caster({25, 3, 25}, 1)}).submerged);     // above the water
  EXPECT_FALSE(f.plan(no_shadows, {sphere_caster({25, -60, 25}, 1)}).submerged);   // below the floor
  EXPECT_TRUE(f.plan(no_shadows, {sphere_caster({25, 3, 25}, 1)}).shadow_rects.empty());
}

// The map's texels follow the camera's pixels at the nearest caster: nearer, a finer map.
TEST(FramePlan, ShadowMapResolutionFollowsTheNearestCaster) {
  const Frame f;
  const double near = nearest_caster_pixels(std::vector{sphere_caster({25, 1, 40}, 1)}, f.view_proj, f.camera.height);
  const double far = nearest_caster_pixels(std::vector{sphere_caster({25, 1, 5}, 1)}, f.view_proj, f.camera.height);
  EXPECT_GT(near, far);
  EXPECT_EQ(nearest_caster_pixels({}, f.view_proj, f.camera.height), 0.0);
  const FramePlan p = f.plan({}, {sphere_caster({25, 1, 40}, 1)});
  ASSERT_TRUE(p.shadow.has_value());
  EXPECT_GE(p.shadow->size, kMinShadowMapSize);
  EXPECT_LE(p.shadow->size, kMaxShadowMapSize);
}

TEST(FrameUniforms, CarryTheCameraLightPondAndStateLayout) {
  const Frame f;
  view::LightingSpec lighting = f.scene.lighting;
  lighting.sun = {0.0, 2.0, 0.0};  // any length: the uniforms carry it normalized
  const auto u = frame_uniforms({f.model, lighting, f.camera, f.view_proj, 2608, 52, nullptr});
  EXPECT_EQ(std::memcmp(u.view_proj.m, f.view_proj.data(), sizeof u.view_proj.m), 0);
  EXPECT_FLOAT_EQ(u.eye.x, static_cast<float>(f.camera.eye[0]));
  EXPECT_FLOAT_EQ(u.eye.z, static_cast<float>(f.camera.eye[2]));
  EXPECT_FLOAT_EQ(POND_FRAME_GRID_SPACING(u), f.model.spacing);
  EXPECT_FLOAT_EQ(u.sun.y, 1.0f);
  EXPECT_FLOAT_EQ(u.sun.x, 0.0f);
  EXPECT_FLOAT_EQ(POND_FRAME_FLOOR_DEPTH(u), static_cast<float>(f.scene.basin.floor_depth));
  EXPECT_FLOAT_EQ(POND_FRAME_LAND_HEIGHT(u), static_cast<float>(f.scene.basin.land_height));
  EXPECT_EQ(POND_FRAME_ROWS(u), static_cast<std::uint32_t>(f.model.rows));
  EXPECT_EQ(POND_FRAME_COLS(u), static_cast<std::uint32_t>(f.model.cols));
  EXPECT_EQ(POND_FRAME_STATE_STRIDE(u), 2608u);
  EXPECT_EQ(POND_FRAME_STATE_PITCH(u), 52u);
  EXPECT_FLOAT_EQ(u.screen.x, 1.0f / 640.0f);
  EXPECT_FLOAT_EQ(u.screen.y, 1.0f / 400.0f);
  EXPECT_FLOAT_EQ(u.screen.z, kReflectionShift);
  // Straight down the sun falls straight down under the water too.
  EXPECT_NEAR(u.shadow_sun.y, -1.0f, 1e-6f);
  const GridSize map = caustics_extent(f.model.rows, f.model.cols);
  EXPECT_EQ(u.caustics_size.x, map.width);
  EXPECT_EQ(u.caustics_size.y, map.height);
  // Without a shadow map the shadow matrix stays zero; with one it is the map's.
  for (float m : u.shadow.m) EXPECT_EQ(m, 0.0f);
  const FramePlan p = f.plan({}, {sphere_caster({25, 1, 25}, 2)});
  ASSERT_TRUE(p.shadow.has_value());
  const auto with = frame_uniforms({f.model, lighting, f.camera, f.view_proj, 2608, 52, &*p.shadow});
  EXPECT_EQ(std::memcmp(with.shadow.m, p.shadow->texture.data(), sizeof with.shadow.m), 0);
}

// Calm water lands the sun's ray through node (j, i) on map coordinates (j, i) / (cols-1, rows-1):
// the lookup undoes the calm refraction's offset for any depth.
TEST(CausticsGrid, LookupUndoesTheCalmOffsetAndTheGridFitsItsLimits) {
  const Frame f;
  const std::array<double, 3> sun = unit(f.scene.lighting.sun);
  const std::array<float, 4> c = caustics_lookup(f.model, sun);
  const shared::caustics::CausticsPush push = caustics_push(f.model, sun, f.scene.basin.floor_depth, 2608, 52);
  // The floor point calm water's ray through the rest point (x, 0, z) reaches.
  const double x = 10.0, z = 20.0, depth = f.scene.basin.floor_depth, h = f.model.spacing;
  const double fx = x + push.light.x * h, fz = z + push.light.y * h;
  EXPECT_NEAR(fx * c[0] + -depth * c[2], x / (h * (f.model.cols - 1)), 1e-6);
  EXPECT_NEAR(fz * c[1] + -depth * c[3], z / (h * (f.model.rows - 1)), 1e-6);
  for (int n : {2, 50, 65, 66, 257, 1025}) {
    const GridSize rays = caustics_rays(n, n), map = caustics_extent(n, n);
    EXPECT_LE(rays.width - 1, static_cast<std::uint32_t>(shared::caustics::kCausticsRays)) << n;
    EXPECT_LE(map.width, static_cast<std::uint32_t>(std::max(shared::caustics::kCausticsTexels, static_cast<int>(rays.width - 1)))) << n;
    EXPECT_EQ(map.width % (rays.width - 1), 0u) << n;
  }
}

}  // namespace
}  // namespace pond::view
