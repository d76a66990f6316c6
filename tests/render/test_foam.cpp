// Foam (render/foam_pass.h) on lavapipe, validation on: the wake of a dragged sphere whitens and
// the white fades after the sphere stops; with foam off nothing whitens and the foam's pass makes
// and records nothing; calm water looks the same with and without it; and the physics' bits are
// the same either way (foam is drawn, never fed back).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "core/png.h"
#include "drawn_session.h"
#include "golden.h"
#include "gpu_fixture.h"
#include "image_compare.h"
#include "render/foam_pass.h"
#include "render/render_target.h"
#include "scene/scene.h"
#include "sim/state.h"
#include "view/view_projection.h"

namespace pond::test {
namespace {

// A sphere dragged half across the pond in 120 steps, then held.
const char* kDraggedThroughFoam = R"({"grid": {"rows": 97, "cols": 97},
  "bodies": [{"shape": "sphere", "radius": 3.0, "motion": "kinematic",
              "path": [[0, 20.0, 0.5, 48.0], [120, 70.0, 0.5, 48.0]]}]})";
const char* kCalmForFoam = R"({"grid": {"rows": 97, "cols": 97}})";

double luminance(const Rgba& img, int x, int y) {
  const std::size_t k = (static_cast<std::size_t>(y) * img.width + x) * 4;
  return 0.2126 * img.pixels[k] + 0.7152 * img.pixels[k + 1] + 0.0722 * img.pixels[k + 2];
}

class FoamTest : public GpuTest {
 protected:
  // A pond drawn every `steps_per_frame` steps, as the demo draws it, foam on or off.
  struct Pond {
    Pond(const gpu::Context& ctx, const char* json, bool foam, sim::SolverChoice solver = {})
        : d(ctx, scene::parse_scene(json, "test"), solver, render::RenderTarget::kFormat), target(ctx, kWidth, kHeight) {
      view.camera = d.loop.default_camera(kWidth, kHeight);
      view.effects.foam = foam;
      view.effects.caustics = false;  // the water's own colour, not the floor's light
    }
    Rgba run(std::int64_t steps, std::int64_t steps_per_frame) {
      for (std::int64_t done = 0; done < steps; done += steps_per_frame) {
        d.session.advance(steps_per_frame);
        view.wait = done + steps_per_frame >= steps;
        d.loop.frame(target.frame_target(), view);
      }
      return Rgba{kWidth, kHeight, target.read_rgba()};
    }
    DrawnSession d;
    render::RenderTarget target;
    render::FrameView view;
  };
  // The loop's foam pass, found by name as a tool would.
  static render::FoamPass& foam_of(Pond& p) {
    auto* foam = dynamic_cast<render::FoamPass*>(p.d.loop.pass("foam"));
    if (!foam) throw std::logic_error("the frame loop has no foam pass");
    return *foam;
  }

  // The pixels of the surface behind the sphere (world x 32..60 along its path, z = 48 +- 2).
  std::vector<std::array<int, 2>> wake_pixels(const Pond& p) const {
    const std::array<float, 16> m = view::view_projection(p.view.camera, p.d.session.model());
    std::vector<std::array<int, 2>> out;
    for (double x = 32; x <= 60; x += 2)
      for (double z = 46; z <= 50; z += 2) {
        double c[4];
        for (int r = 0; r < 4; ++r) c[r] = m[r] * x + m[8 + r] * z + m[12 + r];
        out.push_back({static_cast<int>((c[0] / c[3] * 0.5 + 0.5) * kWidth),
                       static_cast<int>((c[1] / c[3] * 0.5 + 0.5) * kHeight)});
      }
    return out;
  }
  // How much brighter `on` is than `off` over the wake: the mean, and the share of pixels
  // brighter by more than 4 levels.
  std::array<double, 2> whitening(const Rgba& on, const Rgba& off, const std::vector<std::array<int, 2>>& px) const {
    double sum = 0;
    int brighter = 0;
    for (const auto& q : px) {
      const double d = luminance(on, q[0], q[1]) - luminance(off, q[0], q[1]);
      sum += d;
      brighter += d > 4 ? 1 : 0;
    }
    const double n = static_cast<double>(px.size());
    return {sum / n, brighter / n};
  }
  void save(const char* name, const Rgba& img) const {
    std::filesystem::create_directories(POND_TEST_OUT_DIR);
    write_png(std::filesystem::path(POND_TEST_OUT_DIR) / name, img.width, img.height, img.pixels);
  }
};

TEST_F(FoamTest, TheWakeOfADraggedSphereWhitensAndFadesAfterItStops) {
  Pond on(ctx(), kDraggedThroughFoam, true), off(ctx(), kDraggedThroughFoam, false);
  const std::vector<std::array<int, 2>> wake = wake_pixels(on);
  const Rgba on_dragged = on.run(120, 2), off_dragged = off.run(120, 2);
  const std::array<double, 2> dragged = whitening(on_dragged, off_dragged, wake);
  // 250 steps (100 time units, 2.5 times shared::foam::kFoamFade) after the sphere stopped.
  const Rgba on_later = on.run(250, 5), off_later = off.run(250, 5);
  const std::array<double, 2> later = whitening(on_later, off_later, wake);
  std::printf("wake with foam against without: %.1f levels brighter, %.0f%% of its pixels, at the stop; "
              "%.1f levels, %.0f%% 250 steps later\n",
              dragged[0], 100 * dragged[1], later[0], 100 * later[1]);
  save("foam_dragged.png", on_dragged);
  save("foam_dragged_off.png", off_dragged);
  save("foam_later.png", on_later);
  EXPECT_GT(dragged[0], 12.0);
  EXPECT_GT(dragged[1], 0.6);
  EXPECT_LT(later[0], 0.35 * dragged[0]);
  EXPECT_TRUE(foam_of(on).made());
  // Foam off: the pass made nothing and recorded nothing (no foam time in the frames' timestamps).
  EXPECT_FALSE(foam_of(off).made());
  EXPECT_FALSE(off.d.loop.recorded("foam"));
  EXPECT_TRUE(on.d.loop.recorded("foam"));
  // The foam is drawn, never fed back: the same bits with it and without (a guard for the future,
  // should a pass ever share the solver's buffers).
  const std::vector<float> a = sim::to_world_interleaved(on.d.session.state(), on.d.session.model());
  const std::vector<float> b = sim::to_world_interleaved(off.d.session.state(), off.d.session.model());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
}

// The foam is gathered from the displacements the frame draws, which a CPU solver's frame has
// too: the same foam, bit for bit, whichever solver moves the water.
TEST_F(FoamTest, TheCpuSolversFoamIsTheGpuSolvers) {
  Pond gpu(ctx(), kDraggedThroughFoam, true), cpu(ctx(), kDraggedThroughFoam, true, {.gpu = false});
  gpu.run(60, 2);
  cpu.run(60, 2);
  const std::vector<float> a = foam_of(gpu).read(), b = foam_of(cpu).read();
  ASSERT_EQ(a.size(), b.size());
  double most = 0;
  for (float f : a) most = std::max(most, static_cast<double>(f));
  EXPECT_GT(most, 0.5);  // the wake has foam to compare
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
}

// Water that goes back in time (reset to rest) starts again without foam, and gathers it again.
TEST_F(FoamTest, WaterResetToRestHasNoFoam) {
  Pond p(ctx(), kDraggedThroughFoam, true);
  p.run(60, 2);
  p.d.session.reset();
  p.d.loop.frame(p.target.frame_target(), p.view);
  for (float f : foam_of(p).read()) ASSERT_EQ(f, 0.0f);
  p.run(60, 2);
  double most = 0;
  for (float f : foam_of(p).read()) most = std::max(most, static_cast<double>(f));
  EXPECT_GT(most, 0.5);
}

// Calm water gathers no foam, and no foam changes no pixel.
TEST_F(FoamTest, CalmWaterLooksTheSameWithAndWithoutFoam) {
  Pond on(ctx(), kCalmForFoam, true), off(ctx(), kCalmForFoam, false);
  const Rgba a = on.run(30, 3), b = off.run(30, 3);
  EXPECT_EQ(a.pixels, b.pixels);
  const std::vector<float> foam = foam_of(on).read();
  ASSERT_EQ(foam.size(), 97u * 97u);
  for (float f : foam) ASSERT_EQ(f, 0.0f);
}

}  // namespace
}  // namespace pond::test
