// The wind tree's level of detail (tree/tree_lod.h) and the mesh order it relies on (no GPU):
//  - the mesh lists segments by level (trunk first) and its tubes wind counter-clockwise seen from
//    outside (the tube pipeline culls back faces);
//  - the bent bounding sphere holds every drawn vertex in any wind, in both bend modes;
//  - at demo_257's own camera the thin levels are twig lines, the trunk a tube and the leaves
//    triangles; near the tree, and with the camera inside its sphere, every level is a tube and
//    the leaves diamonds.
// tests/render/test_tree_lod.cpp draws the same choices on the GPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "sim/model.h"
#include "scene/scene.h"
#include "tree/bend.h"
#include "tree/noise.h"
#include "tree/tree_lod.h"
#include "tree/tree_mesh.h"
#include "view/view_projection.h"

namespace pond::test {
namespace {

using tree::Vec3;

const std::string kDemoScene = std::string(POND_SCENES_DIR) + "/demo_257.json";

// ---- The mesh's order and winding (no GPU) --------------------------------------------------------

TEST(TreeMeshOrder, SegmentsByLevelTrunkFirst) {
  const tree::Tree t = tree::grow_tree({.depth = 6, .seed = 2});
  const tree::TreeMesh m = tree::build_tree_mesh(t);
  // Lines: the tip of each line's segment, in order, never rises in level.
  int previous = t.depth;
  for (std::uint32_t k = m.lines.all.first; k < m.lines.all.first + m.lines.all.count; k += 2) {
    const int level = t.levels[m.indices[k + 1]];
    EXPECT_LE(level, previous);
    previous = level;
  }
  for (int level = 0; level <= t.depth + 1; ++level) {
    std::size_t at_least = 0, quads = 0;
    for (std::size_t i = 1; i < t.size(); ++i)
      if (t.levels[i] >= level) {
        ++at_least;
        quads += t.levels[i] <= 2 ? 4 : 6;
      }
    EXPECT_EQ(m.lines.at_least(level).count, 2 * at_least) << "level " << level;
    EXPECT_EQ(m.tubes.at_least(level).count, 6 * quads) << "level " << level;
    // The rest of each range is the levels below.
    EXPECT_EQ(m.lines.below(level).first, m.lines.all.first + m.lines.at_least(level).count);
    EXPECT_EQ(m.lines.at_least(level).count + m.lines.below(level).count, m.lines.all.count);
    // One level alone: every segment of it, just after the levels above.
    std::size_t exactly = 0;
    for (std::size_t i = 1; i < t.size(); ++i) exactly += t.levels[i] == level ? 1 : 0;
    EXPECT_EQ(m.lines.level(level).count, 2 * exactly) << "level " << level;
    EXPECT_EQ(m.lines.level(level).first, m.lines.all.first + m.lines.at_least(level + 1).count) << "level " << level;
    EXPECT_EQ(m.tubes.at_least(level).count + m.tubes.below(level).count, m.tubes.all.count);
  }
  EXPECT_EQ(m.tubes.at_least(1).count, m.tubes.all.count);
  EXPECT_EQ(m.lines.below(1).count, 0u);
  // The twig lines' vertices mirror the skeleton's, with their tube's diameter.
  ASSERT_EQ(m.twig_vertices, static_cast<std::int32_t>(t.size()));
  for (std::size_t i = 0; i < t.size(); ++i) {
    const tree::TreeMeshVertex& v = m.vertices[t.size() + i];
    EXPECT_EQ(v.info.x, i);
    EXPECT_EQ(v.info.y, shared::tree_wind::kTreeMaterialTwig);
    EXPECT_GT(v.offset.w, 0.0f);
    EXPECT_EQ(v.offset.x, 0.0f);
  }
}

// Back-face culling keeps a tube's outside only if every triangle faces out.
TEST(TreeMeshOrder, TubeTrianglesFaceOutward) {
  const tree::Tree t = tree::grow_tree({.depth = 5, .seed = 4});
  const tree::TreeMesh m = tree::build_tree_mesh(t);
  auto rest = [&](std::uint32_t k) {
    const tree::TreeMeshVertex& v = m.vertices[m.indices[k]];
    return v.branch.position + Vec3{v.offset.x, v.offset.y, v.offset.z};
  };
  for (std::uint32_t k = m.tubes.all.first; k < m.tubes.all.first + m.tubes.all.count; k += 3) {
    const Vec3 face = tree::cross(rest(k + 1) - rest(k), rest(k + 2) - rest(k));
    Vec3 outward{};
    for (std::uint32_t c = 0; c < 3; ++c) {
      const auto& n = m.vertices[m.indices[k + c]].normal;
      outward = outward + Vec3{n.x, n.y, n.z};
    }
    ASSERT_GT(tree::dot(face, outward), 0.0f) << "tube triangle " << (k - m.tubes.all.first) / 3;
  }
}

// Pruning draws a prefix of a level's lines, or of the far leaves: any prefix must be a uniform
// sample of the crown, not one bough (the skeleton's own, depth-first order would be). Measured by
// the share of each octant about the crown's centroid in the first quarter against in all, which a
// uniform random sample of q points keeps within about sqrt(p (1 - p) / q) (p ~ 1/8): the bound is
// four times that.
TEST(TreeMeshOrder, PrefixesAreUniformSamplesOfTheCrown) {
  const tree::Tree t = tree::grow_tree({.depth = 8, .seed = 5});
  const tree::TreeMesh m = tree::build_tree_mesh(t);
  auto worst_octant_error = [](const std::vector<Vec3>& points) {
    Vec3 mean{};
    for (const Vec3& p : points) mean = mean + p * (1.0f / static_cast<float>(points.size()));
    auto octant = [&](const Vec3& p) { return (p.x > mean.x) | (p.y > mean.y) << 1 | (p.z > mean.z) << 2; };
    std::array<double, 8> all{}, prefix{};
    const std::size_t quarter = points.size() / 4;
    for (std::size_t i = 0; i < points.size(); ++i) {
      all[octant(points[i])] += 1.0 / static_cast<double>(points.size());
      if (i < quarter) prefix[octant(points[i])] += 1.0 / static_cast<double>(quarter);
    }
    double worst = 0;
    for (int o = 0; o < 8; ++o) worst = std::max(worst, std::abs(prefix[o] - all[o]));
    return worst;
  };
  auto bound = [](std::size_t n) { return 4.0 * std::sqrt(0.125 * 0.875 / static_cast<double>(n / 4)); };
  // The far leaves' triangles, by their first corner's branch vertex (the twig's tip).
  std::vector<Vec3> leaves;
  for (std::uint32_t k = 0; k < m.leaf_triangles.count; k += 3)
    leaves.push_back(t.vertices[m.vertices[m.indices[m.leaf_triangles.first + k]].info.x].position);
  ASSERT_EQ(leaves.size(), m.leaves.count / 6);
  ASSERT_GE(leaves.size(), 1000u);
  EXPECT_LT(worst_octant_error(leaves), bound(leaves.size())) << worst_octant_error(leaves);
  // Each thin level's lines, by their tip.
  for (int level = 1; level <= 3; ++level) {
    const tree::IndexRange r = m.lines.level(level);
    std::vector<Vec3> tips;
    for (std::uint32_t k = 0; k < r.count; k += 2) {
      const std::uint32_t tip = m.indices[r.first + k + 1];
      EXPECT_EQ(t.levels[tip], level);
      tips.push_back(t.vertices[tip].position);
    }
    ASSERT_GE(tips.size(), 200u) << "level " << level;
    EXPECT_LT(worst_octant_error(tips), bound(tips.size())) << "level " << level << ": " << worst_octant_error(tips);
  }
  // The skeleton's order fails the same measure: the test can tell.
  std::vector<Vec3> skeleton;
  for (std::size_t i = 1; i < t.size(); ++i)
    if (t.levels[i] == 1) skeleton.push_back(t.vertices[i].position);
  EXPECT_GT(worst_octant_error(skeleton), 2 * bound(skeleton.size())) << worst_octant_error(skeleton);
}

// The far leaves grow about their centres (tree.vert): each corner carries its triangle's centroid,
// packed relative to the longest leaf, to within the packing's step.
TEST(TreeMeshOrder, LeafTrianglesCarryTheirCentres) {
  const tree::Tree t = tree::grow_tree({.depth = 6, .seed = 3});
  const tree::TreeMesh m = tree::build_tree_mesh(t);
  auto unpack = [&](std::uint32_t w, int byte) {
    return std::max(static_cast<float>(static_cast<std::int8_t>(w >> (8 * byte) & 255u)) / 127.0f, -1.0f) * m.longest_leaf;
  };
  for (std::uint32_t k = 0; k < m.leaf_triangles.count; k += 3) {
    Vec3 centroid{};
    for (int c = 0; c < 3; ++c) {
      const tree::TreeMeshVertex& v = m.vertices[m.indices[m.leaf_triangles.first + k + c]];
      centroid = centroid + Vec3{v.offset.x, v.offset.y, v.offset.z} * (1.0f / 3.0f);
    }
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t w = m.vertices[m.indices[m.leaf_triangles.first + k + c]].info.w;
      const float step = m.longest_leaf / 127.0f;
      ASSERT_NEAR(unpack(w, 0), centroid.x, step) << "leaf " << k / 3;
      ASSERT_NEAR(unpack(w, 1), centroid.y, step) << "leaf " << k / 3;
      ASSERT_NEAR(unpack(w, 2), centroid.z, step) << "leaf " << k / 3;
      ASSERT_EQ(w >> 24, 0u);
    }
  }
  EXPECT_GT(m.mean_leaf_area, 0.0f);
}

// ---- The pruning (no GPU) -------------------------------------------------------------------------

TEST(TreeLod, PruningKeepsWhatIsBigEnough) {
  for (float measure : {4.0f, 5.0f, 1e6f}) {
    const tree::Pruning p = tree::prune(2187, measure, 4.0f);
    EXPECT_EQ(p.count, 2187u);
    EXPECT_EQ(p.scale, 1.0f);
  }
  EXPECT_EQ(tree::prune(0, 0.5f, 4.0f).count, 0u);
  // A measure that is not a number draws everything rather than nothing.
  EXPECT_EQ(tree::prune(100, std::nanf(""), 4.0f).count, 100u);
}

TEST(TreeLod, PruningKeepsTheCoveredArea) {
  for (std::uint32_t n : {1u, 7u, 729u, 2187u})
    for (float measure : {3.99f, 1.3f, 0.5f, 0.08f, 1e-4f, 0.0f, -1.0f}) {
      const tree::Pruning p = tree::prune(n, measure, 4.0f);
      ASSERT_GE(p.count, 1u);
      ASSERT_LE(p.count, n);
      // The drawn elements stand for all of them...
      const double count = p.count, all = n;
      EXPECT_NEAR(count * p.scale, all, 1e-3 * all) << n << " of " << measure;
      // ...each at most the threshold, and (when more than one is drawn) not much below it.
      if (measure > 0) {
        EXPECT_LE(measure * p.scale, 4.0f * (1 + 1e-5f)) << n << " of " << measure;
        if (p.count > 1) {
          EXPECT_GT(measure * p.scale, 4.0 * (count - 1) / count) << n << " of " << measure;
        }
      }
    }
  // The demo's far crown: 2187 leaves of 1.3 px^2 are 711 of 4 px^2.
  EXPECT_EQ(tree::prune(2187, 1.3f, 4.0f).count, 711u);
}

// ---- The bounds and the choice (no GPU) -----------------------------------------------------------

TEST(TreeLod, BentBoundsHoldEveryDrawnVertex) {
  const tree::Tree t = tree::grow_tree({.depth = 7, .seed = 5});
  const tree::TreeMesh m = tree::build_tree_mesh(t);
  const tree::TreeBounds b = tree::tree_bounds(t, m);
  const tree::NoiseTable noise = tree::make_noise_table(3);
  for (tree::BendMode mode : {tree::BendMode::article, tree::BendMode::keep_length})
    for (float strength : {0.0f, 4.0f, 9.0f}) {
      tree::WindState state;
      const tree::UserWind user{.strength = strength, .direction = 2.0f};
      for (int step = 0; step < 120; ++step) {
        tree::advance_wind(state, noise, user, 1.0 / 10.0);
        const tree::TreeWindFrame f = tree::wind_frame(state, noise, user, mode);
        const std::vector<Vec3> bent = tree::bend_tree(t, f);
        const tree::Sphere s = tree::bent_bounds(b, f);
        float worst = 0.0f;
        for (const tree::TreeMeshVertex& v : m.vertices) {
          const Vec3 p = bent[v.info.x] + Vec3{v.offset.x, v.offset.y, v.offset.z};
          worst = std::max(worst, tree::length(p - s.centre) - s.radius);
        }
        ASSERT_LE(worst, 0.0f) << "strength " << strength << " step " << step;
      }
    }
}

struct DemoView {
  scene::Scene scene;
  sim::WaterModel model;
  tree::Tree tree;
  tree::TreeBounds bounds;
  float scale = 0;
  Vec3 foot;

  DemoView() : scene(scene::load_scene(kDemoScene)), model(sim::build_model(scene)) {
    const tree::TreeSpec& spec = *scene.tree;
    tree = tree::grow_tree({.depth = spec.depth, .seed = spec.seed});
    const tree::TreeMesh mesh = tree::build_tree_mesh(tree);
    bounds = tree::tree_bounds(tree, mesh);
    longest_leaf = mesh.longest_leaf;
    scale = static_cast<float>(spec.height) / mesh.rest_height;
    const auto& rc = spec.positions.at(0);  // row, col (the loader's default: the island's centre)
    foot = {static_cast<float>(rc[1] * model.spacing), static_cast<float>(scene.basin.land_height),
            static_cast<float>(rc[0] * model.spacing)};
  }

  float pixels_per_unit(const lod::Camera& camera) const {
    const std::array<float, 16> vp = view::view_projection(camera, model);
    const tree::TreeLodCamera c = tree::tree_lod_camera(vp.data(), camera.height);
    const tree::Sphere s = bounds.rest;
    return tree::nearest_pixels_per_unit(c, {foot + s.centre * scale, s.radius * scale}, scale);
  }
  int thinnest_tube(const lod::Camera& camera) const { return tree::thinnest_tube_level(pixels_per_unit(camera), tree.depth); }
  bool diamonds(const lod::Camera& camera) const { return tree::diamond_leaves(pixels_per_unit(camera), longest_leaf); }
  float longest_leaf = 0;
};

TEST(TreeLod, DemoCameraDrawsThinLevelsAsLines) {
  const DemoView d;
  ASSERT_EQ(d.scene.tree->positions.size(), 1u);
  const int level = d.thinnest_tube(view::scene_camera(d.scene.camera, d.model, 1280, 720));
  // At least the two thinnest levels (8 of 9 segments) are lines, and the trunk stays a tube.
  EXPECT_GE(level, 3);
  EXPECT_LE(level, d.tree.depth);
  // Smaller viewports see the same tree in fewer pixels: never more tubes.
  EXPECT_GE(d.thinnest_tube(view::scene_camera(d.scene.camera, d.model, 640, 360)), level);
  // Its leaves are a few pixels long: one triangle each.
  EXPECT_FALSE(d.diamonds(view::scene_camera(d.scene.camera, d.model, 1280, 720)));
}

TEST(TreeLod, NearCameraDrawsEveryLevelAsTubes) {
  const DemoView d;
  lod::Camera near;
  near.width = 1280;
  near.height = 720;
  near.eye = {163, 4, 139};  // 11 units from the trunk, looking up into the crown
  near.target = {160, 6, 128};
  near.fovy_degrees = 40;
  EXPECT_EQ(d.thinnest_tube(near), 1);
  EXPECT_TRUE(d.diamonds(near));
  near.eye = {160, 8, 129};  // inside the crown's sphere
  EXPECT_EQ(d.thinnest_tube(near), 1);
  EXPECT_TRUE(d.diamonds(near));
}

}  // namespace
}  // namespace pond::test
