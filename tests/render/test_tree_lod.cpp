// The wind tree's level of detail on the GPU (validation on): the close-up still draws the tree,
// as before; at the demo's distance the twig lines cover about as much, in about the same colour,
// as the tubes they stand for. The LOD's choices themselves: tests/tree/tree_lod_test.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "drawn_session.h"
#include "render/frame_loop.h"
#include "render/render_target.h"
#include "render/tree_drawable.h"
#include "sim/model.h"
#include "scene/scene.h"
#include "tree/tree_lod.h"
#include "view/view_projection.h"

namespace pond::test {
namespace {

const std::string kDemoScene = std::string(POND_SCENES_DIR) + "/demo_257.json";

// ---- On the GPU ---------------------------------------------------------------------------------

class TreeLodRenderTest : public GpuTest {
 protected:
  static constexpr int kWidth = 1280, kHeight = 720;  // the demo's: its tree is ~60 px tall

  // demo_257 after `steps` steps from `camera` (nullptr: the scene's), with or without its tree and
  // with or without the level of detail; `level` and `diamonds` get the LOD's choices.
  Rgba render(bool with_tree, bool lod, const lod::Camera* camera, int* level = nullptr, bool* diamonds = nullptr) {
    scene::Scene scene = scene::load_scene(kDemoScene);
    scene.perturbations.clear();  // a still pond: the pictures differ by the tree alone
    const tree::TreeSpec tree = *scene.tree;
    DrawnSession drawn(ctx(), scene, {}, render::RenderTarget::kFormat);
    render::FrameLoop& loop = drawn.loop;
    render::TreeDrawable drawable(ctx(), loop, tree);
    drawable.set_level_of_detail(lod);
    if (with_tree) loop.add_drawable(drawable);
    render::RenderTarget target(ctx(), kWidth, kHeight);
    drawn.session.advance(25);
    drawn.session.catch_up_wind();
    render::FrameView view;
    view.camera = camera ? *camera : loop.default_camera(kWidth, kHeight);
    view.wait = true;
    view.effects.shadows = false;  // the tree's own pixels: its shadow's level of detail is the map's
    loop.frame(target.frame_target(), view);
    if (level) *level = drawable.thinnest_tube_levels().at(0);
    if (diamonds) *diamonds = drawable.diamond_leaves().at(0);
    return Rgba{kWidth, kHeight, target.read_rgba()};
  }

  // The pixels where `img` differs from `bare` (the tree's footprint) and their mean colour.
  struct Footprint {
    std::size_t pixels = 0;
    double rgb[3] = {0, 0, 0};
  };
  static Footprint footprint(const Rgba& bare, const Rgba& img, const std::vector<bool>& within) {
    Footprint f;
    for (std::size_t p = 0; p < within.size(); ++p) {
      if (!within[p]) continue;
      bool differs = false;
      for (int c = 0; c < 3; ++c) differs |= std::abs(bare.pixels[4 * p + c] - img.pixels[4 * p + c]) > kLevels;
      f.pixels += differs;
      for (int c = 0; c < 3; ++c) f.rgb[c] += img.pixels[4 * p + c];
    }
    std::size_t n = std::count(within.begin(), within.end(), true);
    for (double& c : f.rgb) c /= static_cast<double>(std::max<std::size_t>(n, 1));
    return f;
  }
  static std::vector<bool> differing(const Rgba& a, const Rgba& b) {
    std::vector<bool> out(static_cast<std::size_t>(a.width) * a.height);
    for (std::size_t p = 0; p < out.size(); ++p)
      for (int c = 0; c < 3; ++c) out[p] = out[p] || std::abs(a.pixels[4 * p + c] - b.pixels[4 * p + c]) > kLevels;
    return out;
  }
  static constexpr int kLevels = 4;
};

TEST_F(TreeLodRenderTest, CloseUpStillDrawsTheTreeAsTubes) {
  lod::Camera near;
  near.eye = {163, 4, 139};
  near.target = {160, 6, 128};
  near.fovy_degrees = 40;
  int level = 0;
  bool diamonds = false;
  const Rgba bare = render(false, true, &near), lod = render(true, true, &near, &level, &diamonds);
  EXPECT_EQ(level, 1);
  EXPECT_TRUE(diamonds);
  const std::vector<bool> tree = differing(bare, lod);
  const auto share = static_cast<double>(std::count(tree.begin(), tree.end(), true)) / static_cast<double>(tree.size());
  EXPECT_GT(share, 0.05) << "the close-up shows little of the tree";
  // All tubes: the level of detail changes nothing here.
  EXPECT_EQ(compare(render(true, false, &near), lod, 0).share, 0.0);
}

// At the demo's own distance most of the tree is twig lines and the leaves are triangles: its
// footprint and colour stay close to those of the full tubes and diamonds, also with the far
// leaves and twigs pruned (measured: 1203 px against 1101, 9% more, 3.6-4.6 levels darker on
// average, as the twigs' averaged light is a little darker than the prisms' facets; before the
// pruning 8% more, 3-5 levels darker). Opaque lines, ignoring the tube's width, would draw 2032 px
// instead of 1101, 25-37 levels darker.
TEST_F(TreeLodRenderTest, TwigLinesLookLikeTheTubesTheyReplace) {
  int level = 0;
  bool diamonds = true;
  const Rgba bare = render(false, true, nullptr), lod = render(true, true, nullptr, &level, &diamonds),
             tubes = render(true, false, nullptr);
  EXPECT_GE(level, 3);
  EXPECT_FALSE(diamonds);
  // The tree's area: every pixel either picture changed, grown by a pixel each way.
  std::vector<bool> area = differing(bare, lod), changed = differing(bare, tubes);
  for (std::size_t p = 0; p < area.size(); ++p) area[p] = area[p] || changed[p];
  std::vector<bool> grown = area;
  for (int y = 1; y + 1 < kHeight; ++y)
    for (int x = 1; x + 1 < kWidth; ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (area[static_cast<std::size_t>((y + dy) * kWidth + x + dx)]) grown[static_cast<std::size_t>(y * kWidth + x)] = true;
  const Footprint a = footprint(bare, lod, grown), b = footprint(bare, tubes, grown);
  ASSERT_GT(b.pixels, 300u) << "the tree is not in the picture";
  EXPECT_NEAR(static_cast<double>(a.pixels), static_cast<double>(b.pixels), 0.12 * static_cast<double>(b.pixels));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.rgb[c], b.rgb[c], 6.0) << "channel " << c;
  std::printf("tree footprint at %dx%d, thinnest tube level %d: %zu px (lod) vs %zu px (tubes); mean rgb "
              "%.1f %.1f %.1f vs %.1f %.1f %.1f\n",
              kWidth, kHeight, level, a.pixels, b.pixels, a.rgb[0], a.rgb[1], a.rgb[2], b.rgb[0], b.rgb[1], b.rgb[2]);
}

}  // namespace
}  // namespace pond::test
