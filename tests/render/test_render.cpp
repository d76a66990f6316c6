// Golden images of the water renderer on lavapipe (labels image, gpu), validation on (any message
// fails). Each case renders 256x160 through the same FrameLoop `pond render` and the demo use,
// without caustics (test_caustics.cpp).
//
// Tolerance: an image matches its golden when at most kGoldenShare of its pixels differ by more than
// kGoldenLevels (of 255) in some channel; a failure writes <name>.actual.png and <name>.diff.png (red =
// differing) into the build tree's tests/render/out. Regenerate after a deliberate change:
//   POND_REGENERATE_GOLDENS=1 ctest --test-dir <build> -L image
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/errors.h"
#include "drawn_session.h"
#include "render/frame_loop.h"
#include "core/png.h"
#include "render/render_target.h"
#include "gpu_fixture.h"
#include "golden.h"
#include "image_compare.h"
#include "scene/scene.h"

namespace pond::test {
namespace {

// LOD at 1 px against the full mesh (same state, same camera): at most this share of pixels differs
// by more than kLodLevels. A 1 px error bound moves edges and shading by about a pixel.
constexpr int kLodLevels = 16;
constexpr double kLodShare = 0.02;

struct RenderCase {
  std::int64_t steps = 0;
  double tolerance = 1.0;
  bool wireframe = false;
  sim::SolverChoice solver{};
  std::string json{};  // empty: the embedded default scene
  vk::Format format = render::RenderTarget::kFormat;
  bool caustics = false;
};

// The scenes: the embedded default (island + splash), and small variations of it.
const char* kIslands = R"({"grid": {"rows": 50, "cols": 50},
  "constraints": [{"kind": "fixed", "rows": [12, 20], "cols": [28, 38]},
                  {"kind": "fixed", "rows": [30, 33], "cols": [10, 14]}],
  "perturbations": [{"step": 0, "row": 26, "col": 24, "radius": 2.0, "amplitude": 1.2}]})";
const char* kPool = R"({"grid": {"rows": 50, "cols": 50}, "border": "vertical",
  "perturbations": [{"step": 0, "row": 24.5, "col": 24.5, "radius": 2.5, "amplitude": 1.5}]})";
const char* kAllVertical = R"({"grid": {"rows": 50, "cols": 50}, "border": "vertical",
  "constraints": [{"kind": "vertical", "rows": [0, 49], "cols": [0, 49]}],
  "perturbations": [{"step": 0, "row": 18, "col": 16, "radius": 2.0, "amplitude": 1.5},
                    {"step": 0, "row": 30, "col": 34, "radius": 2.0, "amplitude": 1.5}]})";
const char* kRippled129 = R"({"grid": {"rows": 129, "cols": 129},
  "constraints": [{"kind": "fixed", "rows": [70, 82], "cols": [80, 95]}],
  "perturbations": [{"step": 0, "row": 40, "col": 40, "radius": 3.0, "amplitude": 1.5},
                    {"step": 10, "row": 90, "col": 50, "radius": 2.0, "amplitude": 1.0},
                    {"step": 20, "row": 50, "col": 100, "radius": 2.5, "amplitude": -1.2}]})";

class RenderTest : public GpuTest {
 protected:
  Rgba render(const RenderCase& c) {
    const scene::Scene scene = scene::parse_scene(c.json.empty() ? std::string(scene::default_scene_json()) : c.json, "test");
    DrawnSession d(ctx(), scene, c.solver, c.format);
    return draw(d, c);
  }

  // Advances an existing session by c.steps and draws one frame of it (c's view settings and format).
  Rgba draw(DrawnSession& d, const RenderCase& c) {
    render::FrameLoop& loop = d.loop;
    render::RenderTarget target(ctx(), kWidth, kHeight, c.format);
    d.session.advance(c.steps);
    render::FrameView view;
    view.camera = loop.default_camera(kWidth, kHeight);
    view.lod_tolerance_px = c.tolerance;
    view.wireframe = c.wireframe;
    // The goldens are the picture without caustics, as before they existed: `view.caustics`
    // false gives the old picture (test_caustics.cpp has the pictures with them).
    view.effects.caustics = c.caustics;
    view.wait = true;
    last_ = loop.frame(target.frame_target(), view);
    return Rgba{kWidth, kHeight, target.read_rgba()};
  }

  render::FrameStats last_;
};

TEST_F(RenderTest, PondAtRest) { expect_golden("rest", render({.steps = 0})); }

TEST_F(RenderTest, RingsAfterASplash) { expect_golden("rings", render({.steps = 24})); }

TEST_F(RenderTest, Islands) { expect_golden("islands", render({.steps = 30, .json = kIslands})); }

TEST_F(RenderTest, VerticalOnlyPool) { expect_golden("pool", render({.steps = 30, .json = kPool})); }

TEST_F(RenderTest, AllVerticalWavesPassThrough) {
  expect_golden("all_vertical", render({.steps = 26, .json = kAllVertical}));
}

// An sRGB target (a swapchain without a UNORM format) gets linear colour from the shaders (a
// specialization constant turns their encoding off) and encodes on store; the clear colour is not
// encoded on the CPU: the same picture as the UNORM target, where the shaders encode. (Not the
// wireframe: its alpha blend mixes encoded values in a UNORM target.)
TEST_F(RenderTest, SrgbTargetShowsTheSamePictureAsUnorm) {
  const RenderCase c{.steps = 24};
  ASSERT_FALSE(render::is_srgb(c.format));
  const Rgba unorm = render(c);
  RenderCase srgb = c;
  srgb.format = vk::Format::eR8G8B8A8Srgb;
  const ImageDiff d = compare(unorm, render(srgb), 2);
  std::printf("sRGB vs UNORM target: largest difference %d levels, %.3f%% of pixels beyond 2\n", d.max_difference,
              100 * d.share);
  EXPECT_LE(d.share, 0.001);
  // And both encoded: with one encoding missing the picture would be much darker or lighter.
  EXPECT_LE(d.max_difference, 8);
}

TEST_F(RenderTest, LodOnAndOffAndTheirDifferenceIsBounded) {
  const Rgba lod = render({.steps = 60, .tolerance = 1.0, .json = kRippled129});
  const std::size_t lod_triangles = last_.triangles;
  const Rgba full = render({.steps = 60, .tolerance = 0.0, .json = kRippled129});
  EXPECT_EQ(last_.triangles, last_.full_triangles);
  EXPECT_LT(lod_triangles, last_.full_triangles);
  expect_golden("lod_1px", lod);
  expect_golden("lod_full", full);
  const ImageDiff d = compare(full, lod, kLodLevels);
  std::printf("LOD 1 px vs full mesh: %zu of %zu triangles, %.3f%% of pixels differ by more than %d levels\n",
              lod_triangles, last_.full_triangles, 100 * d.share, kLodLevels);
  EXPECT_LE(d.share, kLodShare);
}

TEST_F(RenderTest, LodWireframeOverlay) {
  expect_golden("lod_wireframe", render({.steps = 60, .tolerance = 1.0, .wireframe = true, .json = kRippled129}));
}

// The CPU solver gives the GPU's bits (the parity suite), so the frame loop must draw the same
// picture from either, and switching solvers mid-run carries the state over.
TEST_F(RenderTest, CpuSolverDrawsTheSamePictureAndSwitchingCarriesTheState) {
  // With caustics: their pass reads the water's buffers too, which a switch replaces.
  const Rgba gpu_img = render({.steps = 24, .caustics = true});
  const Rgba cpu_img = render({.steps = 24, .solver = {.gpu = false}, .caustics = true});
  EXPECT_EQ(compare(gpu_img, cpu_img, 0).share, 0.0);

  const scene::Scene scene = scene::load_scene("");
  DrawnSession d(ctx(), scene, {.gpu = false}, render::RenderTarget::kFormat);
  render::FrameLoop& loop = d.loop;
  render::RenderTarget target(ctx(), kWidth, kHeight);
  render::FrameView view;
  view.camera = loop.default_camera(kWidth, kHeight);
  view.wait = true;
  view.effects.foam = false;  // foam gathers over the frames drawn: this run draws three, the other one
  d.session.advance(12);
  loop.frame(target.frame_target(), view);   // 12 steps on the CPU
  d.session.set_solver({.gpu = true});
  d.session.advance(4);
  loop.frame(target.frame_target(), view);   // 16 on the GPU
  d.session.set_solver({.gpu = false});
  d.session.advance(8);
  loop.frame(target.frame_target(), view);   // 24 on the CPU
  EXPECT_EQ(d.session.steps_done(), 24);
  EXPECT_EQ(compare(gpu_img, Rgba{kWidth, kHeight, target.read_rgba()}, 0).share, 0.0);
}

// A splash added at run time is the scene's perturbation applied now: same picture.
// The demo's light control: the session's set_sun() draws what a scene with that sun draws; a zero
// or non-finite direction is refused by the scene file's own check, which the demo calls first.
TEST_F(RenderTest, SetSunEqualsTheSceneLightAndRefusesZero) {
  const std::array<double, 3> low_sun{0.8, 0.25, 0.3};
  scene::Scene scene = scene::load_scene("");
  scene.lighting.sun = low_sun;
  DrawnSession scene_lit(ctx(), scene, {}, render::RenderTarget::kFormat);
  const Rgba expected = draw(scene_lit, {.steps = 24});
  EXPECT_GT(compare(render({.steps = 24}), expected, 8).share, 0.05);  // the light visibly moved

  DrawnSession d(ctx(), scene::load_scene(""), {}, render::RenderTarget::kFormat);
  EXPECT_NO_THROW(scene::check_sun(low_sun));
  d.session.set_sun(low_sun);
  EXPECT_THROW(scene::check_sun({0.0, 0.0, 0.0}), InputError);
  EXPECT_THROW(scene::check_sun({std::nan(""), 1.0, 0.0}), InputError);
  EXPECT_EQ(compare(expected, draw(d, {.steps = 24}), 0).share, 0.0);
}

TEST_F(RenderTest, RunTimeSplashEqualsTheScenePerturbation) {
  const char* no_splash = R"({"constraints": [{"kind": "fixed", "rows": [30, 35], "cols": [30, 36]}]})";
  const scene::Scene scene = scene::parse_scene(no_splash, "test");
  DrawnSession d(ctx(), scene, {}, render::RenderTarget::kFormat);
  d.session.splash(scene::load_scene("").perturbations.at(0));
  EXPECT_EQ(compare(render({.steps = 24}), draw(d, {.steps = 24}), 0).share, 0.0);
}

// The demo prepares a frame for the swapchain's size and may draw it into a recreated swapchain of
// another size: the passes prepare() submitted for the old size (the reflection's target among
// them) are made again for the new one, and the picture is the one drawn at that size directly.
TEST_F(RenderTest, AFrameSimulatedForAnotherSizeIsDrawnAsAtItsOwn) {
  const scene::Scene scene = scene::parse_scene(std::string(scene::default_scene_json()), "test");
  auto frame = [&](bool resized) {
    DrawnSession d(ctx(), scene, {}, render::RenderTarget::kFormat);
    render::RenderTarget target(ctx(), kWidth, kHeight);
    d.session.advance(24);
    render::FrameView view;  // every effect on
    view.camera = d.loop.default_camera(kWidth, kHeight);
    view.wait = true;
    if (resized) {
      d.loop.prepare(view, {kWidth / 2, kHeight + 40});
      d.loop.draw(target.frame_target());
    } else {
      d.loop.frame(target.frame_target(), view);
    }
    return Rgba{kWidth, kHeight, target.read_rgba()};
  };
  EXPECT_EQ(compare(frame(true), frame(false), 0).share, 0.0);
}

// POND_REGENERATE_GOLDENS: only "1" regenerates; unset or empty compares; anything else ("0",
// "false", "yes") is refused rather than taken as a wish to rewrite the goldens.
TEST(GoldenMode, OnlyOneRegenerates) {
  EXPECT_EQ(golden_mode(nullptr), GoldenMode::compare);
  EXPECT_EQ(golden_mode(""), GoldenMode::compare);
  EXPECT_EQ(golden_mode("1"), GoldenMode::regenerate);
  for (const char* v : {"0", "false", "no", "yes", "true", "11", " 1", "1 "})
    EXPECT_EQ(golden_mode(v), GoldenMode::invalid) << "'" << v << "'";
}

}  // namespace
}  // namespace pond::test
