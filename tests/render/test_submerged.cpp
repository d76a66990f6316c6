// What clear water shows under its surface (render/submerged_pass.h; labels image, gpu; validation
// on, any message fails): a ball half under calm water, and one sunk, seen from 30 degrees above.
// Which pixels see them through the surface is worked out here, independently of the shaders: from
// the eye to each point of the flat surface, refracted by Snell's law (1 / 1.33), on to the sphere.
// Those pixels must change when the balls are there (measured: 390 of 447 at the commit); the
// pixels whose rays reach the floor beside them must not (5 of 25567); nor must the balls' pixels
// with view.submerged off.
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "pixel_probe.h"
#include "scene_frame.h"
#include "scene/scene.h"
#include "sim/model.h"
#include "view/view_projection.h"

namespace pond::test {
namespace {

constexpr int kSubmergedWidth = 320, kSubmergedHeight = 200;
using V = std::array<double, 3>;

V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V normalized(V a) {
  const double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}

struct Ball {
  V centre;
  double radius;
};

// The first hit of the ray o + s d (d unit) with the ball, if any, at s > 0.
std::optional<double> hit(V o, V d, const Ball& b) {
  const V oc = sub(o, b.centre);
  const double bq = dot(oc, d), c = dot(oc, oc) - b.radius * b.radius, disc = bq * bq - c;
  if (disc < 0) return std::nullopt;
  const double s = -bq - std::sqrt(disc);
  if (s > 0) return s;
  return std::nullopt;
}

// The ray through calm water (normal up) from the eye's direction d at the surface.
V refracted(V d) {
  const double eta = 1.0 / 1.33, cos_i = -d[1], k = 1 - eta * eta * (1 - cos_i * cos_i);
  const double f = eta * cos_i - std::sqrt(k);
  return normalized({eta * d[0], eta * d[1] + f, eta * d[2]});
}

const char* kScene = R"({"grid": {"rows": 65, "cols": 65}, "border": "vertical", "basin": {"floor_depth": 4.0},
  "bodies": [{"shape": "sphere", "radius": 2.5, "motion": "floating", "mass": 32.7, "position": [26.0, 0.0, 36.0]},
             {"shape": "sphere", "radius": 1.2, "motion": "kinematic", "path": [[0, 38.0, -2.6, 40.0]]}],
  "camera": {"eye": [32, 9, 58], "target": [32, -2, 38], "fovy": 50}})";
const char* kEmpty = R"({"grid": {"rows": 65, "cols": 65}, "border": "vertical", "basin": {"floor_depth": 4.0},
  "camera": {"eye": [32, 9, 58], "target": [32, -2, 38], "fovy": 50}})";

class SubmergedTest : public GpuTest {};

TEST_F(SubmergedTest, BallsUnderClearWaterShowRefractedWhereTheirRaysMeetThem) {
  const view::Effects plain{.reflections = false, .caustics = false, .shadows = false};
  const Rgba with = render_scene_frame(ctx(), kScene, plain, kSubmergedWidth, kSubmergedHeight);
  const Rgba without = render_scene_frame(ctx(), kEmpty, plain, kSubmergedWidth, kSubmergedHeight);
  view::Effects off = plain;
  off.submerged = false;
  const Rgba switched_off = render_scene_frame(ctx(), kScene, off, kSubmergedWidth, kSubmergedHeight);
  const scene::Scene scene = scene::parse_scene(kScene, "test");
  const sim::WaterModel model = sim::build_model(scene);
  const std::array<float, 16> vp = view::view_projection(view::scene_camera(scene.camera, model, kSubmergedWidth, kSubmergedHeight), model);
  const V eye = {32, 9, 58};
  const std::array<Ball, 2> balls = {Ball{{26, 0, 36}, 2.5}, Ball{{38, -2.6, 40}, 1.2}};
  // Per pixel: 1 sees a ball through the water, 2 the floor, 3 both (an edge: not judged).
  std::vector<int> seen(static_cast<std::size_t>(kSubmergedWidth) * kSubmergedHeight, 0);
  for (double x = 18; x <= 46; x += 0.02)
    for (double z = 30; z <= 48; z += 0.02) {
      const V w = {x, 0, z}, d = normalized(sub(w, eye));
      bool hidden = false;  // behind a ball's part above the water
      for (const Ball& b : balls)
        if (const auto s = hit(eye, d, b); s && *s < std::sqrt(dot(sub(w, eye), sub(w, eye)))) hidden = true;
      if (hidden) continue;
      bool meets = false;
      for (const Ball& b : balls)
        if (const auto s = hit(w, refracted(d), b); s && w[1] + *s * refracted(d)[1] > -4.0) meets = true;
      const auto [u, v] = project_to_pixel(vp, x, 0, z, kSubmergedWidth, kSubmergedHeight);
      if (u >= 0 && u < kSubmergedWidth && v >= 0 && v < kSubmergedHeight) seen[static_cast<std::size_t>(v) * kSubmergedWidth + u] |= meets ? 1 : 2;
    }
  int ball = 0, ball_changed = 0, floor = 0, floor_changed = 0, off_changed = 0;
  for (int v = 0; v < kSubmergedHeight; ++v)
    for (int u = 0; u < kSubmergedWidth; ++u) {
      const int s = seen[static_cast<std::size_t>(v) * kSubmergedWidth + u];
      const bool changed = std::abs(pixel_brightness(with, u, v) - pixel_brightness(without, u, v)) > 24;
      if (s == 1) ++ball, ball_changed += changed,
                  off_changed += std::abs(pixel_brightness(switched_off, u, v) - pixel_brightness(without, u, v)) > 24;
      if (s == 2) ++floor, floor_changed += changed;
    }
  std::printf("pixels seeing a ball through the water: %d, %d changed; seeing the floor: %d, %d changed\n", ball,
              ball_changed, floor, floor_changed);
  ASSERT_GE(ball, 200) << "the balls' refracted images are too small to judge";
  EXPECT_GE(ball_changed, ball * 8 / 10);
  EXPECT_LE(floor_changed, floor / 50);
  EXPECT_LE(off_changed, ball / 10) << "with view.submerged off the water still shows the balls beneath it";
}

}  // namespace
}  // namespace pond::test
