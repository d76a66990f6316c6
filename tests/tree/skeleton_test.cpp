// The skeleton of SPEC section 2: counts, parent structure, levels, and the AddStick geometry
// (children 120 degrees apart, spread 0.6 len, along-parent length (r + 1.5) / 2 len, len = 0.7^k).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/errors.h"
#include "tree/tree.h"

namespace pond::tree {
namespace {

std::size_t expected_vertices(int depth) {
  std::size_t pow3 = 1;
  for (int k = 0; k < depth; ++k) pow3 *= 3;
  return (pow3 - 1) / 2 + 1;
}

TEST(tree_skeleton, VertexCountsForDepths1To8) {
  EXPECT_EQ(grow_tree({7, 1, 1.0f}).size(), 1094u);  // the article's Step 1
  EXPECT_EQ(grow_tree({8, 1, 1.0f}).size(), 3281u);  // the article's Step 3
  for (int depth = 1; depth <= 8; ++depth) {
    const Tree t = grow_tree({depth, 42, 1.0f});
    EXPECT_EQ(t.size(), expected_vertices(depth)) << "depth " << depth;
    EXPECT_EQ(t.parents.size(), t.size());
    EXPECT_EQ(t.levels.size(), t.size());
    EXPECT_EQ(tree_vertex_count(depth), expected_vertices(depth));
  }
  EXPECT_EQ(tree_vertex_count(10), expected_vertices(10));
}

TEST(tree_skeleton, RejectsDepthOutside1To10) {
  EXPECT_THROW(grow_tree({0, 1, 1.0f}), InternalError);
  EXPECT_THROW(grow_tree({11, 1, 1.0f}), InternalError);
  EXPECT_THROW(grow_tree({3, 1, 0.0f}), InternalError);
}

TEST(tree_skeleton, ParentsPrecedeChildrenAndEveryChainReachesTheRoot) {
  const Tree t = grow_tree({6, 7, 1.0f});
  int roots = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const std::int32_t p = t.parents[i];
    if (p == kNoParent) {
      ++roots;
      EXPECT_EQ(i, 0u) << "the root is vertex 0";
      continue;
    }
    ASSERT_GE(p, 0);
    ASSERT_LT(static_cast<std::size_t>(p), i) << "parent index < child index at " << i;
    // Walk to the root; with parent < child the walk is strictly decreasing, so it ends.
    std::size_t steps = 0;
    for (std::int32_t k = p; k != kNoParent; k = t.parents[static_cast<std::size_t>(k)]) ++steps;
    EXPECT_LE(steps, static_cast<std::size_t>(t.depth));
  }
  EXPECT_EQ(roots, 1);
}

TEST(tree_skeleton, LevelsFromTrunkToTwigs) {
  const int depth = 6;
  const Tree t = grow_tree({depth, 3, 1.0f});
  EXPECT_EQ(t.depth, depth);
  EXPECT_EQ(t.levels[0], kRootLevel);
  EXPECT_EQ(t.levels[1], depth) << "vertex 1 is the trunk's tip";
  std::vector<int> per_level(depth + 1, 0);
  std::vector<int> children(t.size(), 0);
  for (std::size_t i = 1; i < t.size(); ++i) {
    ++per_level[static_cast<std::size_t>(t.levels[i])];
    const auto p = static_cast<std::size_t>(t.parents[i]);
    ++children[p];
    if (p != 0) {
      EXPECT_EQ(t.levels[i], t.levels[p] - 1) << "a child is one level thinner";
    }
  }
  int expected = 1;
  for (int level = depth; level >= 1; --level, expected *= 3)
    EXPECT_EQ(per_level[static_cast<std::size_t>(level)], expected) << "level " << level;
  for (std::size_t i = 1; i < t.size(); ++i)
    EXPECT_EQ(children[i], t.levels[i] == 1 ? 0 : 3) << "vertex " << i;
}

TEST(tree_skeleton, TrunkStandsOnTheOriginAlongY) {
  const Tree t = grow_tree({5, 9, 2.5f});
  EXPECT_EQ(t.vertices[0].position, (Vec3{0, 0, 0}));
  EXPECT_EQ(t.vertices[1].position, (Vec3{0, 2.5f, 0}));
}

// Recomputes, in double, what AddStick promises about each family of three children: with len the
// parent's running length times 0.7 (0.7^k of the trunk at k levels below it, restored between
// siblings), every child's component across its parent's direction has length 0.6 len, the three are
// 120 degrees apart, and the component along the parent is (r + 1.5) / 2 len with r in [0, 1).
TEST(tree_skeleton, ChildrenFollowTheAddStickGeometry) {
  const float trunk = 1.0f;
  const Tree t = grow_tree({5, 11, trunk});
  struct D {
    double x, y, z;
  };
  auto seg = [&](std::size_t i) {
    const Vec3 a = t.vertices[static_cast<std::size_t>(t.parents[i])].position;
    const Vec3 b = t.vertices[i].position;
    return D{double(b.x) - a.x, double(b.y) - a.y, double(b.z) - a.z};
  };
  auto dotd = [](D a, D b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
  std::vector<std::vector<std::size_t>> kids(t.size());
  for (std::size_t i = 1; i < t.size(); ++i) kids[static_cast<std::size_t>(t.parents[i])].push_back(i);
  int families = 0;
  for (std::size_t p = 1; p < t.size(); ++p) {
    if (kids[p].empty()) continue;
    ++families;
    const D dir = seg(p);
    const double dl = std::sqrt(dotd(dir, dir));
    const D u{dir.x / dl, dir.y / dl, dir.z / dl};
    const double len = trunk * std::pow(0.7, t.depth - t.levels[p] + 1);
    std::vector<D> across;
    for (std::size_t c : kids[p]) {
      const D d = seg(c);
      const double along = dotd(d, u);
      const D perp{d.x - along * u.x, d.y - along * u.y, d.z - along * u.z};
      across.push_back(perp);
      // 0.5² + 0.866² = 0.99996: the article's rounded sine shortens two of the three by 2e-5.
      EXPECT_NEAR(std::sqrt(dotd(perp, perp)), 0.6 * len, 1e-4 * len) << "child " << c;
      EXPECT_GE(along, 0.75 * len - 1e-5) << "child " << c;
      EXPECT_LT(along, 1.25 * len + 1e-5) << "child " << c;
    }
    const double s2 = 0.36 * len * len;
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b)  // cos 120° = -0.5 (0.866 in the article: about 1e-4 off)
        EXPECT_NEAR(dotd(across[size_t(a)], across[size_t(b)]) / s2, -0.5, 1e-3);
  }
  EXPECT_EQ(families, 1 + 3 + 9 + 27);
}

}  // namespace
}  // namespace pond::tree
