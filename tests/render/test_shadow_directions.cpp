// The sun's shadow in every direction (labels image, gpu; validation on, any message fails): a
// leafless tree on a small island, three suns around it and, for each, the camera turned to four
// sides of the trunk's shadow on the pool floor (toward the sun, away from it, and across). In each
// view the floor points the law puts in the trunk's shadow (down the sunlight to the water, down
// the refracted sunlight to the floor, seen through the surface where the eye's refracted ray meets
// them) are darker with shadows on than off; the points as far toward the sun are not.
#include <algorithm>
#include <cstdio>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "core/png.h"
#include "golden.h"
#include "gpu_fixture.h"
#include "image_compare.h"
#include "pixel_probe.h"
#include "render/body_drawable.h"
#include "render/render_target.h"
#include "render/tree_drawable.h"
#include "scene/scene.h"
#include "shadow_law.h"
#include "drawn_session.h"
#include "view/sun_shadow.h"
#include "view/view_projection.h"

namespace pond::test {
namespace {

// A 60 x 60 pond, its island 4 x 4 units around (30, 30) (land 1 high, floor 3 deep), a calm
// leafless tree standing at its centre, calm water.
const char* kSmallIslandScene = R"({"grid": {"rows": 60, "cols": 60},
  "constraints": [{"kind": "fixed", "rows": [28, 32], "cols": [28, 32]}],
  "tree": {"depth": 6, "height": 12, "draw": "tubes", "leaves": false}, "wind": {"strength": 0}})";

constexpr double kSmallIslandTrunk[2] = {30.0, 30.0};  // x, z of the trunk (the island's centre)
constexpr double kSmallIslandLo = 28.0, kSmallIslandHi = 32.0;

bool near_small_island(double x, double z, double margin) {
  return x > kSmallIslandLo - margin && x < kSmallIslandHi + margin && z > kSmallIslandLo - margin && z < kSmallIslandHi + margin;
}

// The floor point in the shadow of the trunk's point `up` above the land (null when its sunlight
// enters the water on or beside the island, where the land or its wall may hide it), and its
// mirror through the trunk toward the sun.
struct TrunkFloorShadow {
  std::array<double, 2> shadow, sun_side;
};
std::optional<TrunkFloorShadow> trunk_floor_shadow(const std::array<double, 3>& sun, double up, double land, double depth) {
  const auto step = shadow_step(sun);
  const double height = land + up;  // above the rest plane
  const double ex = kSmallIslandTrunk[0] + step[0] * height, ez = kSmallIslandTrunk[1] + step[1] * height;
  const std::array<float, 3> t = view::sunlight_in_water(sun);
  const double run = depth / -t[1];
  const double fx = ex + t[0] * run, fz = ez + t[2] * run;
  if (near_small_island(ex, ez, 1.0) || near_small_island(fx, fz, 1.0)) return std::nullopt;
  return TrunkFloorShadow{{fx, fz}, {2 * kSmallIslandTrunk[0] - fx, 2 * kSmallIslandTrunk[1] - fz}};
}

class ShadowDirectionsTest : public GpuTest {};

bool on_picture(std::array<int, 2> p) { return p[0] >= 0 && p[0] < kWidth && p[1] >= 0 && p[1] < kHeight; }

// Whether the pixels around p show the same in both pictures (nothing but the water there).
bool same_around(const Rgba& a, const Rgba& b, std::array<int, 2> p) {
  for (int y = std::max(0, p[1] - 1); y <= std::min(kHeight - 1, p[1] + 1); ++y)
    for (int x = std::max(0, p[0] - 1); x <= std::min(kWidth - 1, p[0] + 1); ++x)
      if (std::abs(pixel_brightness(a, x, y) - pixel_brightness(b, x, y)) > 6) return false;
  return true;
}

// The darkest of the 3x3 pixels around p (the trunk's shadow is a line a pixel or two wide, a
// point projected beside it).
int darkest_of_3x3(const Rgba& img, std::array<int, 2> p) {
  int least = 765;
  for (int y = std::max(0, p[1] - 1); y <= std::min(kHeight - 1, p[1] + 1); ++y)
    for (int x = std::max(0, p[0] - 1); x <= std::min(kWidth - 1, p[0] + 1); ++x)
      least = std::min(least, pixel_brightness(img, x, y));
  return least;
}

TEST_F(ShadowDirectionsTest, TheTrunksShadowIsOnTheFloorWhereverTheCameraLooks) {
  const scene::Scene scene = scene::parse_scene(kSmallIslandScene, "test");
  // The pond with the tree, and the same without it (which pixels the tree covers).
  DrawnSession drawn(ctx(), scene, {}, render::RenderTarget::kFormat), bare(ctx(), scene, {}, render::RenderTarget::kFormat);
  render::TreeDrawable tree(ctx(), drawn.loop, *scene.tree);
  drawn.loop.add_drawable(tree);
  render::RenderTarget target(ctx(), kWidth, kHeight);
  const double land = scene.basin.land_height, depth = scene.basin.floor_depth;
  const std::filesystem::path out = POND_TEST_OUT_DIR;
  std::filesystem::create_directories(out);
  auto picture = [&](DrawnSession& d, const render::FrameView& view, const std::string& name) {
    d.loop.frame(target.frame_target(), view);
    Rgba img{kWidth, kHeight, target.read_rgba()};
    pond::write_png(out / (name + ".png"), kWidth, kHeight, img.pixels);
    return img;
  };
  // Low suns from three sides (the default first), so the shadow leaves the island.
  const std::array<std::array<double, 3>, 3> suns{{{-0.3, 0.38, -0.87}, {0.9, 0.42, 0.1}, {-0.5, 0.45, 0.75}}};
  int views = 0;
  for (std::size_t s = 0; s < suns.size(); ++s) {
    drawn.session.set_sun(suns[s]);
    bare.session.set_sun(suns[s]);
    const std::array<double, 3> sun = view::unit(suns[s]);
    // The camera looks at the middle of the floor shadow from eight sides, the first from the
    // sun's, high and low.
    const auto mid = trunk_floor_shadow(sun, 1.4, land, depth);
    ASSERT_TRUE(mid.has_value()) << "sun " << s;
    const double sun_azimuth = std::atan2(sun[2], sun[0]);
    for (int c = 0; c < 16; ++c) {
      const double a = sun_azimuth + (c % 8) * std::acos(-1.0) / 4;
      const double rise = c < 8 ? 14.0 : 7.0;
      render::FrameView view;
      view.camera.target = {mid->shadow[0], -depth, mid->shadow[1]};
      view.camera.eye = {mid->shadow[0] + 20 * std::cos(a), rise, mid->shadow[1] + 20 * std::sin(a)};
      view.camera.fovy_degrees = 50;
      view.camera.width = kWidth, view.camera.height = kHeight;
      view.wait = true;
      const std::array<float, 16> vp = view::view_projection(view.camera, drawn.loop.model());
      const std::string name = "shadow_dir_sun" + std::to_string(s) + "_cam" + std::to_string(c);
      view.effects = view::Effects{.shadows = false};
      const Rgba off = picture(drawn, view, name + "_off"), no_tree = picture(bare, view, name + "_no_tree");
      view.effects = view::Effects{.shadows = true};
      const Rgba on = picture(drawn, view, name + "_on");
      int checked = 0, darker = 0, sun_changed = 0;
      for (double up = 0.3; up <= 2.4; up += 0.1) {
        const auto f = trunk_floor_shadow(sun, up, land, depth);
        if (!f) continue;
        const auto seen = surface_point_seeing(view.camera.eye, f->shadow[0], f->shadow[1], depth);
        const auto p = project_to_pixel(vp, seen[0], 0.0, seen[1]);
        ASSERT_TRUE(on_picture(p)) << name;
        if (!same_around(off, no_tree, p)) continue;  // the tree (or its mirror image) in front
        ++checked;
        if (darkest_of_3x3(on, p) + 15 < darkest_of_3x3(off, p)) ++darker;
        const auto lit = surface_point_seeing(view.camera.eye, f->sun_side[0], f->sun_side[1], depth);
        const auto q = project_to_pixel(vp, lit[0], 0.0, lit[1]);
        if (!near_small_island(f->sun_side[0], f->sun_side[1], 1.0) && on_picture(q) &&
            std::abs(pixel_brightness(on, q[0], q[1]) - pixel_brightness(off, q[0], q[1])) > 12)
          ++sun_changed;
      }
      std::printf("%s: %d of %d darker\n", name.c_str(), darker, checked);
      if (checked < 4) continue;  // the tree hides the shadow from here
      ++views;
      EXPECT_GE(darker, checked * 3 / 4) << name << ": " << darker << " of " << checked
                                         << " floor points in the trunk's shadow are darker";
      EXPECT_EQ(sun_changed, 0) << name << ": the floor toward the sun changed";
    }
  }
  EXPECT_GE(views, 32) << "views where the shadow can be seen";  // two in three: the tree hides the rest
}

}  // namespace
}  // namespace pond::test
