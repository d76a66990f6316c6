// The bodies in the water drawn (issue 16, render/body_drawable.h) on lavapipe, validation on (any
// message fails): each sphere shows its colour at its projected centre, follows the session's
// edits, and the LOD keeps the dent a body makes in the water (LOD at 1 px against the full mesh,
// as the water's own LOD test bounds it). And the icosphere every body is an instance of.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/png.h"
#include "drawn_session.h"
#include "golden.h"
#include "gpu_fixture.h"
#include "image_compare.h"
#include "render/body_drawable.h"
#include "render/render_target.h"
#include "render/sphere_mesh.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "view/view_projection.h"

namespace pond::test {
namespace {

// A kinematic sphere held at the middle (its top above the water) and a floating ball.
const char* kBodies = R"({"grid": {"rows": 50, "cols": 50},
  "bodies": [{"shape": "sphere", "radius": 4.0, "motion": "kinematic", "path": [[0, 24.0, 1.0, 26.0]]},
             {"shape": "sphere", "radius": 3.0, "motion": "floating", "mass": 30.0,
              "position": [12.0, 2.5, 14.0]}]})";
const char* kNoBodies = R"({"grid": {"rows": 50, "cols": 50}})";
// A sphere dragged across a larger pond: a wake and a dent for the LOD to keep.
const char* kDragged = R"({"grid": {"rows": 97, "cols": 97},
  "bodies": [{"shape": "sphere", "radius": 3.0, "motion": "kinematic",
              "path": [[0, 20.0, 0.5, 48.0], [120, 70.0, 0.5, 48.0]]}]})";

struct Pixel {
  int x = 0, y = 0;
};

// Where a world point lands on a width x height image (Vulkan clip space: y down).
Pixel project(const float* m, const std::array<double, 3>& p, int width, int height) {
  double clip[4];
  for (int r = 0; r < 4; ++r) clip[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
  return {static_cast<int>((clip[0] / clip[3] * 0.5 + 0.5) * width),
          static_cast<int>((clip[1] / clip[3] * 0.5 + 0.5) * height)};
}

std::array<int, 3> rgb_at(const Rgba& img, Pixel p) {
  const std::size_t k = (static_cast<std::size_t>(p.y) * img.width + p.x) * 4;
  return {img.pixels[k], img.pixels[k + 1], img.pixels[k + 2]};
}

// The bodies' hues as lit (the sky's bluish ambient mixes in): red well above green and blue; red
// and green well above blue. The water and the land are neither (blue-green, and green).
bool brick_red(const std::array<int, 3>& c) { return c[0] > c[1] + 20 && c[0] > c[2] + 20; }
bool buoy_yellow(const std::array<int, 3>& c) { return c[0] > c[2] + 30 && c[1] > c[2] + 30; }

// A scene drawn as `pond render` draws it, with its bodies.
struct BodyScene {
  BodyScene(const gpu::Context& ctx, const char* json)
      : d(ctx, scene::parse_scene(json, "test"), {}, render::RenderTarget::kFormat), bodies(ctx, d.loop) {
    d.loop.add_drawable(bodies);
  }
  DrawnSession d;
  render::BodyDrawable bodies;
};

class BodyRenderTest : public GpuTest {
 protected:
  // Draws one frame of s (after `steps` more steps), LOD at `tolerance` px.
  Rgba draw(BodyScene& s, std::int64_t steps, double tolerance = 1.0, bool reflections = true) {
    DrawnSession& d = s.d;
    render::RenderTarget target(ctx(), kWidth, kHeight);
    d.session.advance(steps);
    render::FrameView view;
    view.camera = d.loop.default_camera(kWidth, kHeight);
    view.lod_tolerance_px = tolerance;
    view.effects.reflections = reflections;
    view.effects.caustics = false;  // the bodies and the LOD's dents, not the floor's light
    view.wait = true;
    d.loop.frame(target.frame_target(), view);
    drawn_ = s.bodies.drawn();
    view_proj_ = view::view_projection(view.camera, d.session.model());
    return Rgba{kWidth, kHeight, target.read_rgba()};
  }
  // The pixel of the top half of body b's centre line (above the water whatever the dent).
  Pixel body_pixel(sim::Session& s, std::size_t b) const {
    const sim::BodyState st = s.bodies().at(b);
    const double h = s.model().spacing, r = s.water().bodies.at(b).radius;
    return project(view_proj_.data(), {st.x * h, st.y * h + 0.5 * r, st.z * h}, kWidth, kHeight);
  }

  std::size_t drawn_ = 0;
  std::array<float, 16> view_proj_{};
};

TEST_F(BodyRenderTest, EachBodyShowsItsColourWhereItIs) {
  BodyScene with(ctx(), kBodies);
  const Rgba img = draw(with, 5);
  EXPECT_EQ(drawn_, 2u);
  const Pixel sphere = body_pixel(with.d.session, 0), ball = body_pixel(with.d.session, 1);
  BodyScene without(ctx(), kNoBodies);
  const Rgba plain = draw(without, 5);
  EXPECT_EQ(drawn_, 0u);
  const auto c_sphere = rgb_at(img, sphere), c_ball = rgb_at(img, ball), c_water = rgb_at(plain, sphere);
  std::printf("kinematic sphere at (%d, %d): %d %d %d; floating ball at (%d, %d): %d %d %d; water there: %d %d %d\n",
              sphere.x, sphere.y, c_sphere[0], c_sphere[1], c_sphere[2], ball.x, ball.y, c_ball[0], c_ball[1],
              c_ball[2], c_water[0], c_water[1], c_water[2]);
  EXPECT_TRUE(brick_red(c_sphere));
  EXPECT_TRUE(buoy_yellow(c_ball));
  EXPECT_FALSE(brick_red(c_water));
  std::filesystem::create_directories(POND_TEST_OUT_DIR);
  write_png(std::filesystem::path(POND_TEST_OUT_DIR) / "bodies.png", img.width, img.height, img.pixels);
}

// The drawable draws what the session holds now: a ball added at run time appears, a removed
// sphere is gone.
// A sphere held above calm water is mirrored about the waterline: where its centre mirrored to
// -y projects, the water turns toward the sphere's red with reflections on (weighted by Fresnel,
// so redder than the water, not as red as the sphere) and shows no red with them off.
TEST_F(BodyRenderTest, ASphereAboveCalmWaterIsMirroredInIt) {
  const char* json = R"({"grid": {"rows": 50, "cols": 50},
    "camera": {"eye": [24, 3, 49], "target": [24, 1, 20], "fovy": 40},
    "bodies": [{"shape": "sphere", "radius": 3.0, "motion": "kinematic", "path": [[0, 24.0, 4.0, 22.0]]}]})";
  BodyScene on(ctx(), json), off(ctx(), json);
  const Rgba with = draw(on, 1, 1.0, true);
  const Rgba without = draw(off, 1, 1.0, false);
  const Pixel body = project(view_proj_.data(), {24.0, 4.0, 22.0}, kWidth, kHeight);
  const Pixel mirror = project(view_proj_.data(), {24.0, -4.0, 22.0}, kWidth, kHeight);
  ASSERT_GT(mirror.y, body.y + 10) << "the mirror image lies below the sphere on screen";
  EXPECT_TRUE(brick_red(rgb_at(with, body)));
  EXPECT_TRUE(brick_red(rgb_at(without, body)));
  const std::array<int, 3> a = rgb_at(with, mirror), b = rgb_at(without, mirror);
  const auto sum = [](const std::array<int, 3>& c) { return c[0] + c[1] + c[2]; };
  EXPECT_LT(sum(a), sum(b) - 80) << "no dark mirror image: " << a[0] << "," << a[1] << "," << a[2] << " against "
                                 << b[0] << "," << b[1] << "," << b[2];
  EXPECT_GT(a[0] - a[2], b[0] - b[2] + 15) << "the mirror image is not the sphere's red";
  EXPECT_LT(b[0], b[2]) << "a red mirror image without reflections";
  for (const int dx : {-45, 45}) {  // the water beside the mirror image: sky in both
    const Pixel side{mirror.x + dx, mirror.y};
    EXPECT_LT(std::abs(sum(rgb_at(with, side)) - sum(rgb_at(without, side))), 30) << dx;
  }
}

TEST_F(BodyRenderTest, FollowsTheSessionsEdits) {
  BodyScene s(ctx(), kBodies);
  draw(s, 2);
  const Pixel sphere = body_pixel(s.d.session, 0);
  s.d.session.remove_body(0);
  s.d.session.add_body({.shape = sim::BodyShape::sphere, .motion = sim::BodyMotion::floating, .radius = 3.0, .mass = 30.0,
                      .position = {36.0, 2.5, 14.0}, .velocity = {}, .path = {}});
  const Rgba img = draw(s, 2);
  EXPECT_EQ(drawn_, 2u);
  EXPECT_FALSE(brick_red(rgb_at(img, sphere)));
  EXPECT_TRUE(buoy_yellow(rgb_at(img, body_pixel(s.d.session, 1))));
}

// The contact moves the water's nodes and the LOD builder reads the moved state: at 1 px the dent
// and the wake around a dragged sphere stay within the water's own LOD bound of the full mesh.
TEST_F(BodyRenderTest, LodKeepsTheDentAroundADraggedSphere) {
  BodyScene lod(ctx(), kDragged);
  const Rgba at_1px = draw(lod, 80, 1.0);
  BodyScene full(ctx(), kDragged);
  const Rgba full_mesh = draw(full, 80, 0.0);
  const ImageDiff d = compare(full_mesh, at_1px, 16);
  std::printf("dragged sphere, LOD 1 px vs full mesh: %.3f%% of pixels differ by more than 16 levels\n", 100 * d.share);
  EXPECT_LE(d.share, 0.02);
}

TEST(SphereMesh, ClosedUnitAndWoundOutward) {
  const render::SphereMesh m = render::build_sphere_mesh(3);
  EXPECT_EQ(m.indices.size(), 20u * 64u * 3u);
  EXPECT_EQ(m.points.size(), 642u);  // V - E + F = 2 with E = 3F/2
  for (const auto& p : m.points) EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 1e-6);
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const auto& a = m.points[m.indices[t]];
    const auto& b = m.points[m.indices[t + 1]];
    const auto& c = m.points[m.indices[t + 2]];
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    ASSERT_GT(n[0] * (a[0] + b[0] + c[0]) + n[1] * (a[1] + b[1] + c[1]) + n[2] * (a[2] + b[2] + c[2]), 0.0) << t;
  }
}

// The level of detail's premise: each subdivision about halves the longest edge, and the finest
// level the drawable has (4) keeps the outline within half a pixel up to a radius of 500 px (wider
// than a 720-pixel-high window).
TEST(SphereMesh, LevelsHalveTheEdgeAndTheFinestIsSmoothUpClose) {
  double previous = render::longest_edge(render::build_sphere_mesh(0));
  for (int s = 1; s <= 4; ++s) {
    const double edge = render::longest_edge(render::build_sphere_mesh(s));
    EXPECT_LT(edge, 0.6 * previous) << s;
    EXPECT_GT(edge, 0.4 * previous) << s;
    previous = edge;
  }
  EXPECT_LE(render::outline_error_px(500.0, previous), 0.5);
  EXPECT_GT(render::outline_error_px(500.0, render::longest_edge(render::build_sphere_mesh(3))), 0.5);
}

}  // namespace
}  // namespace pond::test
