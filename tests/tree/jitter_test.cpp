// Twig-jitter coefficients: only the three thinnest levels carry them, bounded by
// |dir| * {0.3, 0.15, 0.075} / 2 per component.
#include <gtest/gtest.h>

#include <cmath>

#include "tree/jitter_coefficients.h"
#include "tree/tree.h"

namespace pond::tree {
namespace {

TEST(tree_jitter, NonzeroOnlyOnTheThreeThinnestLevels) {
  for (int depth : {2, 5, 8}) {
    const Tree t = grow_tree({depth, 13, 1.0f});
    EXPECT_EQ(t.vertices[0].jitter, (Vec3{})) << "root";
    for (std::size_t i = 1; i < t.size(); ++i) {
      const Vec3 c = t.vertices[i].jitter;
      const int level = t.levels[i];
      if (level > 3) {
        EXPECT_EQ(c, (Vec3{})) << "level " << level << " vertex " << i;
        continue;
      }
      EXPECT_NE(c, (Vec3{})) << "level " << level << " vertex " << i;
      const auto p = static_cast<std::size_t>(t.parents[i]);
      const float len = length(t.vertices[i].position - t.vertices[p].position);
      const float half = 0.5f * len * (level == 1 ? 0.3f : level == 2 ? 0.15f : 0.075f);
      for (float v : {c.x, c.y, c.z}) EXPECT_LE(std::abs(v), half * (1 + 1e-6f)) << "vertex " << i;
    }
  }
}

TEST(tree_jitter, AmplitudeHalvesPerLevel) {
  EXPECT_FLOAT_EQ(jitter_amplitude(2.0f, 1), 0.6f);
  EXPECT_FLOAT_EQ(jitter_amplitude(2.0f, 2), 0.3f);
  EXPECT_FLOAT_EQ(jitter_amplitude(2.0f, 3), 0.15f);
  EXPECT_EQ(jitter_amplitude(2.0f, 4), 0.0f);
  EXPECT_EQ(jitter_amplitude(2.0f, 0), 0.0f);
}

TEST(tree_jitter, CoefficientsSpreadOverTheirRange) {
  // Uniform in [-half, half): the three components of the twigs of a depth-8 tree average near 0
  // and fill most of the range, so twigs do not all answer the noise alike.
  const Tree t = grow_tree({8, 2, 1.0f});
  double sum = 0, max_ratio = 0;
  int n = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t.levels[i] != 1) continue;
    const auto p = static_cast<std::size_t>(t.parents[i]);
    const double half = 0.15 * length(t.vertices[i].position - t.vertices[p].position);
    for (float v : {t.vertices[i].jitter.x, t.vertices[i].jitter.y, t.vertices[i].jitter.z}) {
      sum += v / half;
      max_ratio = std::max(max_ratio, std::abs(v / half));
      ++n;
    }
  }
  EXPECT_EQ(n, 3 * 2187);
  EXPECT_NEAR(sum / n, 0.0, 0.03);
  EXPECT_GT(max_ratio, 0.99);
}

}  // namespace
}  // namespace pond::tree
