// Clear water (issue 27; labels image, gpu; validation on, any message fails): the water absorbs
// per world unit of path (Beer-Lambert per colour channel, lighting.absorption), so a calm pool
// three units deep seen from 45 degrees above shows its floor's pattern with at least half the
// contrast it has with absorption off, and the grid's spacing does not change how clear it is.
#include <cmath>
#include <cstdio>
#include <string>

#include "gpu_fixture.h"
#include "scene_frame.h"

namespace pond::test {
namespace {

constexpr int kClearWidth = 320, kClearHeight = 200;

// A calm pool with vertical walls, 3 units deep and 64 units across at `spacing`, seen from 45
// degrees above its middle; `lighting` is the scene's lighting object's keys.
std::string calm_pool(double spacing, const std::string& lighting) {
  const int nodes = static_cast<int>(std::lround(64 / spacing)) + 1;
  return R"({"grid": {"rows": )" + std::to_string(nodes) + R"(, "cols": )" + std::to_string(nodes) +
         R"(, "spacing": )" + std::to_string(spacing) + R"(}, "border": "vertical",
    "basin": {"floor_depth": 3.0}, "camera": {"eye": [32, 20, 12], "target": [32, 0, 32]},
    "lighting": {)" + lighting + "}}";
}

// The standard deviation of the linear luminance over the middle half of the picture (all water).
double contrast(const Rgba& image) {
  double sum = 0, sum2 = 0;
  int n = 0;
  for (int y = image.height / 4; y < 3 * image.height / 4; ++y)
    for (int x = image.width / 4; x < 3 * image.width / 4; ++x) {
      const double l = linear_luminance(image, x, y);
      sum += l, sum2 += l * l, ++n;
    }
  const double mean = sum / n;
  return std::sqrt(std::max(sum2 / n - mean * mean, 0.0));
}

class ClearWaterTest : public GpuTest {
 protected:
  // The floor's contrast through the pool at `spacing`, over the same with absorption off.
  double kept_contrast(double spacing) {
    const Rgba clear = render_scene_frame(ctx(), calm_pool(spacing, ""), view::Effects{}, kClearWidth, kClearHeight);
    const Rgba none =
        render_scene_frame(ctx(), calm_pool(spacing, R"("absorption": [0, 0, 0])"), view::Effects{}, kClearWidth, kClearHeight);
    const double kept = contrast(clear) / contrast(none);
    std::printf("spacing %.2f: the floor's contrast through 3 units of calm water is %.2f of it without absorption\n",
                spacing, kept);
    return kept;
  }
};

TEST_F(ClearWaterTest, TheFloorShowsThroughCalmWaterWithHalfItsContrast) { EXPECT_GE(kept_contrast(1.0), 0.5); }

// Absorption is per world unit: a pond of the same size on a grid twice as fine is as clear.
TEST_F(ClearWaterTest, TheGridSpacingDoesNotChangeHowClearTheWaterIs) {
  const double coarse = kept_contrast(1.0), fine = kept_contrast(0.5);
  EXPECT_NEAR(fine, coarse, 0.1);
}

// Murky water (a scene's own absorption, ten times pure water's) hides the floor.
TEST_F(ClearWaterTest, MurkyWaterHidesTheFloor) {
  const Rgba murky = render_scene_frame(ctx(), calm_pool(1.0, R"("absorption": [3, 0.6, 0.1])"), view::Effects{},
                                        kClearWidth, kClearHeight);
  const Rgba none =
      render_scene_frame(ctx(), calm_pool(1.0, R"("absorption": [0, 0, 0])"), view::Effects{}, kClearWidth, kClearHeight);
  EXPECT_LT(contrast(murky), 0.5 * contrast(none));
}

}  // namespace
}  // namespace pond::test
