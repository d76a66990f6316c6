// The CPU bend evaluation: the article's formula per vertex, and the length-preserving variant.
#include <gtest/gtest.h>

#include <cmath>

#include "tree/bend.h"
#include "tree/tree.h"

namespace pond::tree {
namespace {

TreeWindFrame frame_with(float wx, float wz, Vec3 q, BendMode mode) {
  TreeWindFrame f{};
  f.wind = {wx, 0, wz, 0};
  f.twig = {q.x, q.y, q.z, 0};
  f.bend_mode = static_cast<std::uint32_t>(mode);
  return f;
}

TEST(tree_bend, ArticleFormulaPerVertexRecomputedInDouble) {
  const Tree t = grow_tree({6, 21, 1.0f});
  const Vec3 q{0.7f, -1.1f, 0.4f};
  const float wx = 0.2f, wz = -0.13f;
  const std::vector<Vec3> bent = bend_tree(t, frame_with(wx, wz, q, BendMode::article));
  for (std::size_t i = 0; i < t.size(); ++i) {
    const TreeVertex& v = t.vertices[i];
    const double j = double(v.jitter.x) * q.x + double(v.jitter.y) * q.y + double(v.jitter.z) * q.z;
    const double ax = wx + j, az = wz + j;
    EXPECT_NEAR(bent[i].x, v.position.x + v.wind_x.x * ax + v.wind_z.x * az, 1e-5);
    EXPECT_NEAR(bent[i].y, v.position.y + v.wind_x.y * ax + v.wind_z.y * az, 1e-5);
    EXPECT_NEAR(bent[i].z, v.position.z + v.wind_x.z * ax + v.wind_z.z * az, 1e-5);
  }
}

TEST(tree_bend, CalmAirLeavesTheRestPoseExactlyInBothModes) {
  const Tree t = grow_tree({6, 21, 1.0f});
  for (BendMode mode : {BendMode::article, BendMode::keep_length}) {
    const std::vector<Vec3> bent = bend_tree(t, frame_with(0, 0, {}, mode));
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (mode == BendMode::article) {
        EXPECT_EQ(bent[i], t.vertices[i].position) << "vertex " << i;
      } else {  // rescaled by the exact-math rsqrt: equal to float rounding
        EXPECT_NEAR(length(bent[i] - t.vertices[i].position), 0.0f, 1e-5f) << "vertex " << i;
      }
    }
  }
}

TEST(tree_bend, TrunkBaseNeverMoves) {
  const Tree t = grow_tree({5, 2, 1.0f});
  for (BendMode mode : {BendMode::article, BendMode::keep_length})
    EXPECT_EQ(bend_tree(t, frame_with(0.4f, 0.3f, {1, 2, 3}, mode))[0], (Vec3{}));
}

TEST(tree_bend, WindPushesTheCrownDownwind) {
  const Tree t = grow_tree({7, 2, 1.0f});
  for (BendMode mode : {BendMode::article, BendMode::keep_length}) {
    const std::vector<Vec3> bent = bend_tree(t, frame_with(0.25f, 0, {}, mode));
    double mean_dx = 0;
    for (std::size_t i = 0; i < t.size(); ++i) mean_dx += bent[i].x - t.vertices[i].position.x;
    EXPECT_GT(mean_dx / double(t.size()), 0.1);
  }
}

// The article's bend stretches branches (each tip moves perpendicular to its branch, so a twig of
// stiffness factor s grows by sqrt(1 + (s w)^2)); the length-preserving variant does not.
TEST(tree_bend, KeepLengthPreservesSegmentLengthsWhileTheArticleStretches) {
  const Tree t = grow_tree({8, 1, 1.0f});
  for (float w : {0.05f, 0.25f, 0.45f}) {
    const StretchStats article = measure_stretch(t, w, 0.0f, BendMode::article);
    const StretchStats kept = measure_stretch(t, w, 0.0f, BendMode::keep_length);
    const double twig = std::sqrt(1.0 + (7.3 * w) * (7.3 * w)) - 1.0;  // level 1 at depth 8
    EXPECT_NEAR(article.max_relative, twig, 0.05 * twig) << "wind " << w;
    EXPECT_LT(kept.max_relative, 1e-5) << "wind " << w;
    EXPECT_LT(kept.mean_relative, 1e-6) << "wind " << w;
  }
  // With jitter and a diagonal wind too.
  const TreeWindFrame f = frame_with(0.2f, -0.25f, {3, -2, 4}, BendMode::keep_length);
  EXPECT_LT(measure_stretch(t, bend_tree(t, f)).max_relative, 1e-5);
}

TEST(tree_bend, KeepLengthKeepsTheArticlesSegmentDirections) {
  const Tree t = grow_tree({6, 4, 1.0f});
  const TreeWindFrame a = frame_with(0.3f, 0.1f, {1, 1, -1}, BendMode::article);
  TreeWindFrame k = a;
  k.bend_mode = shared::tree_wind::kTreeBendKeepLength;
  const std::vector<Vec3> article = bend_tree(t, a), kept = bend_tree(t, k);
  for (std::size_t i = 1; i < t.size(); ++i) {
    const auto p = static_cast<std::size_t>(t.parents[i]);
    const Vec3 da = article[i] - article[p], dk = kept[i] - kept[p];
    EXPECT_NEAR(dot(da, dk) / (length(da) * length(dk)), 1.0f, 1e-5f) << "vertex " << i;
  }
}

TEST(tree_bend, StretchGrowsWithWind) {
  const Tree t = grow_tree({7, 3, 1.0f});
  double previous = 0;
  for (float w : {0.0f, 0.05f, 0.1f, 0.2f, 0.4f}) {
    const StretchStats s = measure_stretch(t, 0.0f, w, BendMode::article);
    EXPECT_GE(s.mean_relative, previous);
    EXPECT_LE(s.mean_relative, s.max_relative);
    previous = s.mean_relative;
  }
}

}  // namespace
}  // namespace pond::tree
