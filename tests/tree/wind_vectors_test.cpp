// The per-vertex wind vectors, checked against an independent recomputation in double: the own
// vector of a branch is the unit-wind axis with its component along the branch removed (a projection
// instead of the article's double cross product), normalized and scaled by |dir| (0.3 + D - level);
// the stored vector is the sum of the own vectors along the chain to the root.
#include <gtest/gtest.h>

#include <cmath>

#include "tree/tree.h"
#include "tree/wind_vectors.h"

namespace pond::tree {
namespace {

struct D3 {
  double x = 0, y = 0, z = 0;
};
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dotd(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 crossd(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
D3 d3(Vec3 v) { return {v.x, v.y, v.z}; }

D3 segment(const Tree& t, std::size_t i) {
  return d3(t.vertices[i].position) - d3(t.vertices[static_cast<std::size_t>(t.parents[i])].position);
}

D3 own_reference(const Tree& t, std::size_t i, D3 axis) {
  const D3 dir = segment(t, i);
  const double l = std::sqrt(dotd(dir, dir));
  const D3 u = dir * (1.0 / l);
  const D3 perp = axis - u * dotd(axis, u);
  const double s = l * (0.3 + t.depth - t.levels[i]);
  return perp * (s / std::sqrt(dotd(perp, perp)));
}

D3 accumulated_reference(const Tree& t, std::size_t i, D3 axis) {
  D3 sum;
  for (std::size_t k = i; t.parents[k] != kNoParent; k = static_cast<std::size_t>(t.parents[k]))
    sum = sum + own_reference(t, k, axis);
  return sum;
}

void expect_near(D3 a, Vec3 b, double tol, const char* what, std::size_t i) {
  EXPECT_NEAR(a.x, b.x, tol) << what << " at vertex " << i;
  EXPECT_NEAR(a.y, b.y, tol) << what << " at vertex " << i;
  EXPECT_NEAR(a.z, b.z, tol) << what << " at vertex " << i;
}

TEST(tree_wind_vectors, MatchAnIndependentRecomputation) {
  const Tree t = grow_tree({7, 5, 1.0f});
  const D3 x{1, 0, 0}, z{0, 0, 1};
  for (std::size_t i : {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{100},
                        std::size_t{555}, t.size() - 1}) {
    expect_near(accumulated_reference(t, i, x), t.vertices[i].wind_x, 1e-4, "wind_x", i);
    expect_near(accumulated_reference(t, i, z), t.vertices[i].wind_z, 1e-4, "wind_z", i);
  }
}

TEST(tree_wind_vectors, OwnVectorIsPerpendicularInThePlaneOfBranchAndWindAndScaledByLevel) {
  const Tree t = grow_tree({7, 5, 1.0f});
  const D3 axes[2] = {{1, 0, 0}, {0, 0, 1}};
  for (std::size_t i = 1; i < t.size(); i += 37) {
    const auto p = static_cast<std::size_t>(t.parents[i]);
    const D3 dir = segment(t, i);
    const double l = std::sqrt(dotd(dir, dir));
    for (int a = 0; a < 2; ++a) {
      const D3 mine = a == 0 ? d3(t.vertices[i].wind_x) - d3(t.vertices[p].wind_x)
                             : d3(t.vertices[i].wind_z) - d3(t.vertices[p].wind_z);
      const double m = std::sqrt(dotd(mine, mine));
      EXPECT_NEAR(m, l * (0.3 + t.depth - t.levels[i]), 1e-4 * (1 + m)) << "scale at " << i;
      EXPECT_NEAR(dotd(mine, dir) / (m * l), 0.0, 1e-4) << "perpendicular to the branch at " << i;
      const D3 normal = crossd(dir, axes[a]);  // normal of the plane of branch and wind
      EXPECT_NEAR(dotd(mine, normal) / (m * std::sqrt(dotd(normal, normal))), 0.0, 1e-4)
          << "in the plane of branch and wind at " << i;
      EXPECT_GT(dotd(mine, axes[a]), 0.0) << "downwind at " << i;
    }
  }
}

TEST(tree_wind_vectors, TrunkBaseIsFixedAndTrunkTipBendsByPoint3) {
  const Tree t = grow_tree({4, 5, 2.0f});
  EXPECT_EQ(t.vertices[0].wind_x, (Vec3{}));
  EXPECT_EQ(t.vertices[0].wind_z, (Vec3{}));
  // The trunk (level = depth) is vertical: s = 2.0 * 0.3, straight along the wind.
  EXPECT_NEAR(t.vertices[1].wind_x.x, 0.6f, 1e-6f);
  EXPECT_NEAR(t.vertices[1].wind_x.y, 0.0f, 1e-6f);
  EXPECT_NEAR(t.vertices[1].wind_z.z, 0.6f, 1e-6f);
}

// A hand-made skeleton: a vertical trunk, then one branch exactly along +x and one exactly along +z.
TEST(tree_wind_vectors, BranchParallelToAWindAxisGetsNoOwnVectorAndNoNaN) {
  Tree t;
  t.depth = 2;
  t.vertices.resize(4);
  t.vertices[1].position = {0, 1, 0};
  t.vertices[2].position = {0.5f, 1, 0};  // along +x
  t.vertices[3].position = {0, 1, -0.5f};  // along -z
  t.parents = {kNoParent, 0, 1, 1};
  t.levels = {kRootLevel, 2, 1, 1};
  compute_wind_vectors(t);
  const Vec3 trunk_x = t.vertices[1].wind_x, trunk_z = t.vertices[1].wind_z;
  EXPECT_EQ(t.vertices[2].wind_x, trunk_x) << "parallel to x: only the trunk's displacement";
  EXPECT_EQ(t.vertices[3].wind_z, trunk_z) << "parallel to z: only the trunk's displacement";
  // Across the other axis they bend normally: the x branch under z wind moves along +z.
  EXPECT_NEAR(t.vertices[2].wind_z.z - trunk_z.z, 0.5f * 1.3f, 1e-6f);
  EXPECT_NEAR(t.vertices[3].wind_x.x - trunk_x.x, 0.5f * 1.3f, 1e-6f);
  for (const TreeVertex& v : t.vertices)
    for (float c : {v.wind_x.x, v.wind_x.y, v.wind_x.z, v.wind_z.x, v.wind_z.y, v.wind_z.z})
      EXPECT_TRUE(std::isfinite(c));
  // Nearly parallel (1e-4 rad) is not parallel: full-size own vector, still finite.
  const Vec3 own = own_wind_vector({1.0f, 1e-4f, 0.0f}, {1, 0, 0}, 2.0f);
  EXPECT_NEAR(length(own), 2.0f, 1e-5f);
  EXPECT_LT(own.y, 0.0f) << "pushed away from the axis, toward -y";
}

}  // namespace
}  // namespace pond::tree
