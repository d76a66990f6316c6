// Caustics on the pool floor (render/caustics_pass.h; labels image, gpu; validation on, any message
// fails). The map itself: calm water lights the floor exactly as before (1 everywhere); a splash
// makes rings (texels at one distance from the splash agree far better than texels at different
// distances) of focused (> 1) and spread (< 1) light whose mean stays 1 (the area ratio's energy
// conservation); the CPU solver's uploads give the GPU solver's map. The picture: golden images
// of a splash with caustics on and off, calm water the same with and without them, and the floor
// under a splash changed by them.
// Regenerate the goldens after a deliberate change: POND_REGENERATE_GOLDENS=1 ctest -L image.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "golden.h"
#include "gpu_fixture.h"
#include "image_compare.h"
#include "scene_frame.h"
#include "core/png.h"
#include "render/caustics_pass.h"
#include "render/frame_loop.h"
#include "render/render_target.h"
#include "render/water_source.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "view/sun_shadow.h"

namespace pond::test {
namespace {

// A pool with vertical walls, seen from above so the floor shows through the water.
const char* kCalmPool = R"({"grid": {"rows": 50, "cols": 50}, "border": "vertical",
  "camera": {"eye": [24.5, 20, 42], "target": [24.5, -3, 21]}})";
const char* kSplashPool = R"({"grid": {"rows": 50, "cols": 50}, "border": "vertical",
  "camera": {"eye": [24.5, 20, 42], "target": [24.5, -3, 21]},
  "perturbations": [{"step": 0, "row": 24.5, "col": 24.5, "radius": 2.0, "amplitude": 0.8}]})";
// A gentler, wider splash on a larger pool, for the map's rings (its waves focus the light without
// folding it: the area ratio's law then holds exactly, see below).
const char* kRingsPool = R"({"grid": {"rows": 97, "cols": 97}, "border": "vertical",
  "perturbations": [{"step": 0, "row": 48, "col": 48, "radius": 3.0, "amplitude": 0.4}]})";


struct Map {
  vk::Extent2D extent;
  std::vector<float> light;  // the floor's light relative to calm water, at each texel's first corner
  float direct_share = 0;
  // The area ratio of texel k: light = 1 + share (ratio - 1).
  double ratio(std::size_t k) const { return 1.0 + (light[k] - 1.0) / direct_share; }
};

// Writes the area ratio as a grey picture (0 black, 1 mid grey, 2 and more white), each texel
// `zoom` pixels wide, into the test's output folder, to look at.
void write_ratio_png(const Map& m, const std::string& name, int zoom = 4) {
  const int w = static_cast<int>(m.extent.width), h = static_cast<int>(m.extent.height);
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < h * zoom; ++y)
    for (int x = 0; x < w * zoom; ++x) {
      const double r = m.ratio(static_cast<std::size_t>(y / zoom) * m.extent.width + static_cast<std::size_t>(x / zoom));
      const auto v = static_cast<std::uint8_t>(std::clamp(r * 127.5, 0.0, 255.0));
      rgba.insert(rgba.end(), {v, v, v, 255});
    }
  std::filesystem::create_directories(POND_TEST_OUT_DIR);  // this test may be the first to write there
  write_png(std::string(POND_TEST_OUT_DIR) + "/" + name + ".png", w * zoom, h * zoom, rgba);
}

class CausticsTest : public GpuTest {
 protected:
  // The map of `json`'s water after `steps` steps, computed by the pass alone.
  Map map(const std::string& json, std::int64_t steps, sim::SolverChoice solver = {}) {
    const scene::Scene scene = scene::parse_scene(json, "test");
    gpu::GpuSolvers solvers(ctx());
    sim::Session session(scene::session_spec(scene), solver, solvers.factory());
    session.advance(steps);
    render::WaterSource water(ctx(), session, &solvers);
    water.sync();
    const render::WaterSource::DrawBuffers b = water.prepare(0);
    render::CausticsPass pass(ctx(), session.model(), 1);
    pass.bind(0, *b.state, *b.normals);
    const std::array<double, 3> sun = view::unit(scene.lighting.sun);
    const render::CausticsPush push = view::caustics_push(session.model(), sun, scene.basin.floor_depth, b.stride, b.pitch);
    ctx().submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
      using S = vk::PipelineStageFlagBits2;
      using A = vk::AccessFlagBits2;
      const vk::MemoryBarrier2 visible{.srcStageMask = S::eComputeShader | S::eHost,
                                       .srcAccessMask = A::eShaderWrite | A::eHostWrite,
                                       .dstStageMask = S::eComputeShader, .dstAccessMask = A::eShaderRead};
      cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &visible});
      pass.record(cmd, 0, push);
    });
    return {pass.map(0).extent, pass.read_map(0), view::caustics_direct_share(sun)};
  }

  Rgba render(const std::string& json, std::int64_t steps, bool caustics) {
    return render_scene_frame(ctx(), json, view::Effects{.caustics = caustics}, kWidth, kHeight, steps);
  }
};

TEST_F(CausticsTest, CalmWaterLightsTheFloorAsWithout) {
  const Map m = map(kCalmPool, 20);
  ASSERT_EQ(m.light.size(), std::size_t{m.extent.width} * m.extent.height);
  const auto [lo, hi] = std::minmax_element(m.light.begin(), m.light.end());
  EXPECT_FLOAT_EQ(*lo, 1.0f);
  EXPECT_FLOAT_EQ(*hi, 1.0f);
  // So the picture is the same with and without caustics.
  const ImageDiff d = compare(render(kCalmPool, 20, false), render(kCalmPool, 20, true), 1);
  EXPECT_EQ(d.share, 0.0) << "largest difference " << d.max_difference;
}

// The rings: the splash's waves run out in circles, and so do their caustics: the map, turned a
// quarter about the splash, matches itself (correlation of the ratio's deviation from 1; the sun's
// slant makes it less than 1). And light is neither made nor lost: the mean area ratio over the
// floor stays 1. Exactly so for the exact inverse of the rays' map; the pass's one Newton step
// leaves an excess of the order of |grad d|^2, which reaches 1 only at a focus: a few percent for
// this splash, whose first ring is a sharp focus (1/|det| clamped at kMaxFocus there).
TEST_F(CausticsTest, ASplashFocusesTheLightInRingsAndConservesIt) {
  const Map m = map(kRingsPool, 60);
  write_ratio_png(m, "caustics_map_rings");
  const int w = static_cast<int>(m.extent.width), h = static_cast<int>(m.extent.height);
  ASSERT_EQ(w, h);  // so the quarter turn about the centre (the splash) maps the map onto itself
  // Texel (x, y)'s first value is the light at its corner (x, y); the splash is at corner (w/2, h/2).
  double total = 0, lo = 1e9, hi = 0, cross = 0, self = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double r = m.ratio(static_cast<std::size_t>(y * w + x));
      total += r;
      lo = std::min(lo, r);
      hi = std::max(hi, r);
      if (y == 0) continue;  // its turned corner (w, x) is the map's far edge, not stored
      const double turned = m.ratio(static_cast<std::size_t>(x * w + (w - y)));
      cross += (r - 1) * (turned - 1);
      self += (r - 1) * (r - 1);
    }
  const double mean = total / static_cast<double>(w * h), symmetry = cross / self;
  std::printf("area ratio after a splash: min %.3f, max %.3f, mean %.5f; quarter-turn correlation %.3f\n", lo, hi,
              mean, symmetry);
  EXPECT_LT(lo, 0.8) << "nothing spread the light";
  EXPECT_GT(hi, 1.5) << "nothing focused the light";
  EXPECT_NEAR(mean, 1.0, 0.03);
  EXPECT_GT(symmetry, 0.25) << "not rings";  // measured 0.35; plane waves would give about 0
  // A ring: along a line out from the splash the ratio rises above 1 and falls below it again.
  int crossings = 0;
  for (int x = w / 2 + 1; x + 1 < w; ++x)
    if ((m.ratio(static_cast<std::size_t>(h / 2 * w + x)) - 1.05) * (m.ratio(static_cast<std::size_t>(h / 2 * w + x + 1)) - 1.05) < 0)
      ++crossings;
  EXPECT_GE(crossings, 2);
}

// The CPU solver's path uploads the state and its normals; the GPU solver's are its own buffers.
// Exact math makes both the same bits, so the maps agree.
TEST_F(CausticsTest, CpuSolverGivesTheGpuSolversMap) {
  const Map gpu = map(kSplashPool, 16, sim::SolverChoice{.gpu = true});
  const Map cpu = map(kSplashPool, 16, sim::SolverChoice{.gpu = false, .backend = sim::Backend::scalar});
  ASSERT_EQ(gpu.light.size(), cpu.light.size());
  EXPECT_EQ(gpu.light, cpu.light);
}

// Issue 27's splash: amplitude 1, radius 2, in a pool 3 units deep on a 129² grid, seen from
// straight above.
const char* kCrestPool = R"({"grid": {"rows": 129, "cols": 129}, "border": "vertical", "basin": {"floor_depth": 3.0},
  "camera": {"eye": [64, 48, 64.5], "target": [64, 0, 64], "fovy": 40},
  "perturbations": [{"step": 0, "row": 64, "col": 64, "radius": 2.0, "amplitude": 1.0}]})";

// Under the splash's crest (25 steps on) the map's bright ring is at least 1.3 times calm water's
// light on the floor and its dark band at most 0.8; the rendered floor, in linear light against the
// same frame without caustics, at least 1.2 and at most 0.85 (the 99.5th and 0.5th percentiles of
// the pixels' ratios, so that no single pixel decides).
TEST_F(CausticsTest, ASplashsRingIsBrightAndItsBandDark) {
  const Map m = map(kCrestPool, 25);
  const auto [lo, hi] = std::minmax_element(m.light.begin(), m.light.end());
  const Rgba on = render(kCrestPool, 25, true), off = render(kCrestPool, 25, false);
  std::vector<double> ratio;
  for (int y = 0; y < on.height; ++y)
    for (int x = 0; x < on.width; ++x)
      ratio.push_back(linear_luminance(on, x, y) / std::max(linear_luminance(off, x, y), 1e-6));
  std::sort(ratio.begin(), ratio.end());
  const double dark = ratio[ratio.size() / 200], bright = ratio[ratio.size() - 1 - ratio.size() / 200];
  std::printf("a splash's caustics: the map %.2f .. %.2f of calm water's light; the rendered floor %.2f .. %.2f\n", *lo,
              *hi, dark, bright);
  EXPECT_GE(*hi, 1.3f);
  EXPECT_LE(*lo, 0.8f);
  EXPECT_GE(bright, 1.2);
  EXPECT_LE(dark, 0.85);
}

// Waves seen from 30 to 60 degrees above: switching the caustics off changes at least 1 % of the
// pixels by more than 8 levels (through clear water the floor's light is plain to see).
TEST_F(CausticsTest, SwitchingThemOffVisiblyChangesAPondWithWaves) {
  for (const double degrees : {30.0, 45.0, 60.0}) {
    const double rad = degrees * 3.14159265358979 / 180, back = 40 * std::cos(rad), up = 40 * std::sin(rad);
    const std::string json = R"({"grid": {"rows": 97, "cols": 97}, "border": "vertical",
      "camera": {"eye": [48, )" + std::to_string(up) + ", " + std::to_string(48 + back) + R"(], "target": [48, 0, 48]},
      "perturbations": [{"step": 0, "row": 40, "col": 36, "radius": 2.0, "amplitude": 0.8},
                        {"step": 10, "row": 60, "col": 58, "radius": 1.5, "amplitude": 0.6},
                        {"step": 20, "row": 45, "col": 62, "radius": 2.5, "amplitude": -0.5}]})";
    const ImageDiff d = compare(render(json, 40, false), render(json, 40, true), 8);
    std::printf("caustics on vs off, waves seen from %.0f degrees: %.1f %% of the pixels differ by more than 8 levels\n",
                degrees, 100 * d.share);
    EXPECT_GE(d.share, 0.01) << degrees << " degrees";
  }
}

// Ponds made up from a seed (grid, spacing, depth, an island with a tree, splashes, a camera from
// 20 to 70 degrees above and any side), every effect on: switching the caustics off still changes
// at least 1 % of the pixels by more than 8 levels.
std::string made_up_pond(std::mt19937& rng) {
  const auto pick = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const auto pick_int = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const int n = pick_int(65, 129);
  const double spacing = pick_int(0, 1) ? 0.5 : 1.0, depth = pick(1.5, 4.0);
  const int r0 = pick_int(n / 4, n / 2), c0 = pick_int(n / 4, n / 2), side = pick_int(4, 8);
  std::string splashes;
  for (int k = 0, count = pick_int(2, 4); k < count; ++k)
    splashes += std::string(k ? ", " : "") + R"({"step": )" + std::to_string(8 * k) + R"(, "row": )" +
                std::to_string(pick_int(8, n - 9)) + R"(, "col": )" + std::to_string(pick_int(8, n - 9)) +
                R"(, "radius": )" + std::to_string(pick(1.5, 3.0)) + R"(, "amplitude": )" + std::to_string(pick(0.5, 1.0)) + "}";
  const double elevation = pick(20, 70) * 3.14159265358979 / 180, azimuth = pick(0, 2 * 3.14159265358979);
  const double centre = (n - 1) * spacing / 2, reach = 0.9 * (n - 1) * spacing;
  const double eye_x = centre + reach * std::cos(elevation) * std::cos(azimuth);
  const double eye_z = centre + reach * std::cos(elevation) * std::sin(azimuth);
  return R"({"grid": {"rows": )" + std::to_string(n) + R"(, "cols": )" + std::to_string(n) + R"(, "spacing": )" +
         std::to_string(spacing) + R"(}, "border": "vertical", "basin": {"floor_depth": )" + std::to_string(depth) +
         R"(}, "constraints": [{"kind": "fixed", "rows": [)" + std::to_string(r0) + ", " + std::to_string(r0 + side) +
         R"(], "cols": [)" + std::to_string(c0) + ", " + std::to_string(c0 + side) + R"(]}],
    "tree": {"depth": 6, "draw": "tubes", "positions": [[)" + std::to_string(r0 + side / 2.0) + ", " +
         std::to_string(c0 + side / 2.0) + R"(]]},
    "perturbations": [)" + splashes + R"(],
    "camera": {"eye": [)" + std::to_string(eye_x) + ", " + std::to_string(reach * std::sin(elevation)) + ", " +
         std::to_string(eye_z) + R"(], "target": [)" + std::to_string(centre) + ", 0, " + std::to_string(centre) + "]}}";
}

TEST_F(CausticsTest, SwitchingThemOffVisiblyChangesPondsMadeUpFromASeed) {
  std::mt19937 rng(20261203);
  for (int k = 0; k < 6; ++k) {
    const std::string json = made_up_pond(rng);
    const auto frame = [&](bool caustics) {
      return render_scene_frame(ctx(), json, view::Effects{.caustics = caustics}, kWidth, kHeight, 30);
    };
    const ImageDiff d = compare(frame(false), frame(true), 8);
    std::printf("made-up pond %d: caustics on vs off, %.1f %% of the pixels differ by more than 8 levels\n", k, 100 * d.share);
    EXPECT_GE(d.share, 0.01) << json;
  }
}

TEST_F(CausticsTest, SplashGoldensAndTheFloorChanged) {
  const Rgba on = render(kSplashPool, 40, true), off = render(kSplashPool, 40, false);
  expect_golden("caustics_splash_on", on);
  expect_golden("caustics_splash_off", off);
  const ImageDiff d = compare(off, on, 8);
  std::printf("caustics on vs off after a splash: %.1f%% of pixels differ by more than 8 levels\n", 100 * d.share);
  EXPECT_GT(d.share, 0.02);  // the ring under the splash (measured 4.2 %)
}

}  // namespace
}  // namespace pond::test
