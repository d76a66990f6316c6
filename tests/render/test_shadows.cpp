// The sun's shadows (render/shadow_pass.h; labels image, gpu; validation on, any message fails):
// golden images of the tree's island and of a sphere over calm water with shadows on and off; the
// trunk's shadow falls on the island and the water on the side away from the sun (darker there with
// shadows, unchanged on the sun's side) and is gone with `view.shadows` off; a sphere's shadow
// darkens the pool floor seen through calm water where the refracted sunlight through its centre
// meets it, and not the same distance toward the sun.
// Regenerate the goldens after a deliberate change: POND_REGENERATE_GOLDENS=1 ctest -L image.
#include <algorithm>
#include <array>
#include <cmath>

#include "golden.h"
#include "gpu_fixture.h"
#include "image_compare.h"
#include "pixel_probe.h"
#include "shadow_law.h"
#include "scene_frame.h"
#include "scene/scene.h"
#include "sim/model.h"
#include "view/sun_shadow.h"
#include "view/view_projection.h"

namespace pond::test {
namespace {

// The island of the reflection tests with a calm, leafless tree (its trunk stands free), seen from
// above on the side its shadow falls (the default sun is toward -x, +y, -z: shadows run to +x, +z).
const char* kCalmIslandFromAbove = R"({"constraints": [{"kind": "fixed", "rows": [30, 35], "cols": [30, 36]}],
  "camera": {"eye": [44, 12, 50], "target": [35, 0.5, 35], "fovy": 40},
  "tree": {"depth": 6, "draw": "tubes", "leaves": false, "positions": [[32.5, 33]]},
  "wind": {"strength": 0}})";
// The same island with a leafy tree in the wind after a splash (the golden pictures).
const char* kIslandFromAbove = R"({"constraints": [{"kind": "fixed", "rows": [30, 35], "cols": [30, 36]}],
  "camera": {"eye": [46, 14, 52], "target": [35, 0.5, 35], "fovy": 45},
  "perturbations": [{"step": 0, "row": 40, "col": 20, "radius": 2.0, "amplitude": 1.0}],
  "tree": {"depth": 7, "draw": "tubes", "leaves": true}, "wind": {"strength": 3}})";
// A sphere held above calm water (no contact: its bottom is 1 unit up), seen from nearly overhead,
// so the floor under the water shows where it is (little refraction).
const char* kSphere = R"({"grid": {"rows": 50, "cols": 50},
  "camera": {"eye": [26, 60, 30], "target": [25, 0, 25], "fovy": 40},
  "bodies": [{"shape": "sphere", "radius": 3.0, "motion": "kinematic", "path": [[0, 20.0, 4.0, 20.0]]}]})";

int brightness(const Rgba& img, std::array<int, 2> p) { return pixel_brightness(img, p[0], p[1]); }

// The darkest of the 3x3 pixels around p (a shadow line one pixel wide, a point projected beside it).
int darkest_near(const Rgba& img, std::array<int, 2> p) {
  int least = 765;
  for (int y = std::max(0, p[1] - 1); y <= std::min(img.height - 1, p[1] + 1); ++y)
    for (int x = std::max(0, p[0] - 1); x <= std::min(img.width - 1, p[0] + 1); ++x)
      least = std::min(least, pixel_brightness(img, x, y));
  return least;
}

bool on_image(std::array<int, 2> p) { return p[0] >= 0 && p[0] < kWidth && p[1] >= 0 && p[1] < kHeight; }

class ShadowTest : public GpuTest {
 protected:
  // One frame of `json` (after `steps` steps) with shadows on or off, its tree and bodies drawn.
  Rgba render(const char* json, bool shadows, std::int64_t steps = 0) {
    return render_scene_frame(ctx(), json, view::Effects{.shadows = shadows}, kWidth, kHeight, steps);
  }

  static std::array<float, 16> view_proj(const char* json) {
    const scene::Scene scene = scene::parse_scene(json, "test");
    const sim::WaterModel model = sim::build_model(scene);
    return view::view_projection(view::scene_camera(scene.camera, model, kWidth, kHeight), model);
  }
};

// The trunk's shadow on the island's top in a frame with shadows on and one with them off: trunk
// points 0.15 .. 0.9 above its foot (at `foot`, [row, col]) cast their shadows on the land (which
// ends 2.5 units from the trunk toward +z); mirrored through the foot, the points as far toward the
// sun, which no shadow reaches. Around most shadow points the darkest pixel must be darker with
// shadows on, and no sun-side pixel may change.
void expect_trunk_shadow(const scene::Scene& scene, const std::array<double, 2>& foot, const std::array<float, 16>& vp,
                         const Rgba& on, const Rgba& off, int darker_by) {
  const double h = sim::build_model(scene).spacing;
  const double x = foot[1] * h, z = foot[0] * h;
  const double land = scene.basin.land_height;
  const auto step = shadow_step(scene.lighting.sun);
  int checked = 0, darker = 0, sun_side_changed = 0;
  for (double up = 0.15; up <= 0.9; up += 0.05) {
    const auto p = project_to_pixel(vp, x + step[0] * up, land, z + step[1] * up);
    const auto q = project_to_pixel(vp, x - step[0] * up, land, z - step[1] * up);
    ASSERT_TRUE(on_image(p) && on_image(q)) << "off screen at " << up;
    ++checked;
    if (darkest_near(on, p) + darker_by < darkest_near(off, p)) ++darker;
    if (std::abs(brightness(on, q) - brightness(off, q)) > 12) ++sun_side_changed;
  }
  EXPECT_GE(darker, checked * 3 / 4) << darker << " of " << checked << " land points in the trunk's shadow are darker";
  EXPECT_EQ(sun_side_changed, 0) << "the land toward the sun changed";
}

TEST_F(ShadowTest, TrunkShadowFallsAwayFromTheSunAndGoesWithShadowsOff) {
  const scene::Scene scene = scene::parse_scene(kCalmIslandFromAbove, "test");
  const Rgba on = render(kCalmIslandFromAbove, true), off = render(kCalmIslandFromAbove, false);
  expect_golden_pair("shadow_trunk_on", on, "shadow_trunk_off", off);
  const std::array<float, 16> vp = view_proj(kCalmIslandFromAbove);
  const double h = sim::build_model(scene).spacing;
  const double x = scene.tree->positions[0][1] * h, z = scene.tree->positions[0][0] * h;
  const double land = scene.basin.land_height;
  const auto step = shadow_step(scene.lighting.sun);
  expect_trunk_shadow(scene, scene.tree->positions[0], vp, on, off, 40);
  // Higher up the trunk's shadow reaches past the island onto the water and, down the refracted
  // sunlight, the floor, which the clear water shows where the view ray refracted at the surface
  // meets it. Points on the line of the shadow from 1 to 3 units up whose sunlight enters the
  // water past the island and whose floor point is in the picture.
  const std::array<float, 3> t = view::sunlight_in_water(scene.lighting.sun);
  const double depth = scene.basin.floor_depth;
  int water_checked = 0, water_darker = 0;
  for (double up = 1.0; up <= 3.0; up += 0.1) {
    const double height = land + up;  // above the water's rest plane
    const double sx = x + step[0] * height, sz = z + step[1] * height;
    if (sx >= 30 * h && sx <= 36 * h && sz >= 30 * h && sz <= 35 * h) continue;  // on the island
    const auto seen = surface_point_seeing(scene.camera->eye, sx + t[0] * depth / -t[1], sz + t[2] * depth / -t[1], depth);
    const auto p = project_to_pixel(vp, seen[0], 0.0, seen[1]);
    if (!on_image(p)) continue;
    ++water_checked;
    if (brightness(on, p) + 15 < brightness(off, p)) ++water_darker;
  }
  EXPECT_GE(water_checked, 4);
  EXPECT_GE(water_darker, water_checked / 2) << water_darker << " of " << water_checked << " water points darker";
  // With shadows off nothing of the kind: the picture equals a frame of a scene without the key's
  // effect (the default on, set off by FrameView) -- checked by the golden above; and the tree's
  // own pixels are the same in both.
  const auto trunk = project_to_pixel(vp, x, land + 0.5, z);
  EXPECT_LT(std::abs(brightness(on, trunk) - brightness(off, trunk)), 12);
}

TEST_F(ShadowTest, SphereShadowsTheFloorThroughCalmWater) {
  const scene::Scene scene = scene::parse_scene(kSphere, "test");
  const Rgba on = render(kSphere, true), off = render(kSphere, false);
  expect_golden_pair("shadow_sphere_on", on, "shadow_sphere_off", off);
  const std::array<float, 16> vp = view_proj(kSphere);
  const std::array<double, 3> c{20.0, 4.0, 20.0};  // world (spacing 1)
  const auto& sun = scene.lighting.sun;
  const auto step = shadow_step(sun);
  // Where the sunlight through the centre enters the water, then down the refracted sunlight to
  // the floor; the pixel above that floor point (seen from nearly overhead, refraction shifts it
  // by a tenth of a unit).
  const double sx = c[0] + step[0] * c[1], sz = c[2] + step[1] * c[1];
  const std::array<float, 3> t = view::sunlight_in_water(sun);
  const double depth = scene.basin.floor_depth, run = depth / -t[1];
  const double fx = sx + t[0] * run, fz = sz + t[2] * run;
  int checked = 0, darker = 0, sun_side_changed = 0;
  for (double dx = -0.6; dx <= 0.6; dx += 0.3)
    for (double dz = -0.6; dz <= 0.6; dz += 0.3) {
      const auto p = project_to_pixel(vp, fx + dx, 0.0, fz + dz);
      // As far from the sphere toward the sun: sunlit water in both pictures.
      const auto q = project_to_pixel(vp, 2 * c[0] - fx + dx, 0.0, 2 * c[2] - fz + dz);
      ASSERT_TRUE(on_image(p) && on_image(q));
      ++checked;
      if (brightness(on, p) + 25 < brightness(off, p)) ++darker;
      if (std::abs(brightness(on, q) - brightness(off, q)) > 6) ++sun_side_changed;
    }
  EXPECT_GE(darker, checked * 3 / 4) << darker << " of " << checked << " floor points in the sphere's shadow are darker";
  EXPECT_EQ(sun_side_changed, 0) << "the water toward the sun changed";
}

// Golden pictures of the leafy tree's island after a splash, with and without shadows, told apart
// where they differ; and the trunk's shadow probed as on the calm island (the tree stands at the
// island's centre, its default place).
TEST_F(ShadowTest, IslandGoldens) {
  const Rgba on = render(kIslandFromAbove, true, 12), off = render(kIslandFromAbove, false, 12);
  expect_golden_pair("shadow_island_on", on, "shadow_island_off", off);
  const scene::Scene scene = scene::parse_scene(kIslandFromAbove, "test");
  expect_trunk_shadow(scene, {32.5, 33.0}, view_proj(kIslandFromAbove), on, off, 40);
}

}  // namespace
}  // namespace pond::test
