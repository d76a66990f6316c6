// The land mesh (src/view/land_mesh.cpp) is lit per vertex (shaders/land.vert). That equals the
// per-pixel light only where the light is linear across each triangle: flat faces, and walls cut
// where the wetness ramp bends. These tests hold the mesh to that.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "view/land_mesh.h"
#include "sim/model.h"
#include "scene/scene.h"

namespace pond::view {
namespace {

sim::WaterModel island_model(double floor_depth = 2.0, double land_height = 1.5) {
  scene::Scene scene = scene::parse_scene(R"({"grid": {"rows": 24, "cols": 31},
      "constraints": [{"kind": "fixed", "rows": [8, 14], "cols": [10, 20]}]})",
                                        "test");
  scene.basin = {floor_depth, land_height};
  return sim::build_model(scene, sim::MathMode::exact);
}

// The two heights where clamp(kLandWetAtRest - y / land_height, 0, 1) bends.
std::array<double, 2> wetness_kinks(double land_height) {
  const double k = shared::water_render::kLandWetAtRest;
  return {k * land_height, (k - 1.0) * land_height};
}

TEST(LandMesh, NoTriangleSpansABendOfTheWetness) {
  for (const double land_height : {0.6, 1.5}) {
    const double floor_depth = 2.0;
    const sim::WaterModel model = island_model(floor_depth, land_height);
    const std::vector<LandVertex> mesh = build_land_mesh(model);
    ASSERT_EQ(mesh.size() % 3, 0u);
    int walls = 0, cut = 0;
    for (std::size_t t = 0; t < mesh.size(); t += 3) {
      const float y[3] = {mesh[t].position.y, mesh[t + 1].position.y, mesh[t + 2].position.y};
      const double lo = *std::min_element(y, y + 3), hi = *std::max_element(y, y + 3);
      for (const double kink : wetness_kinks(land_height))
        EXPECT_FALSE(kink > lo + 1e-6 && kink < hi - 1e-6)
            << "triangle " << t / 3 << " spans y = " << kink << " (from " << lo << " to " << hi << ")";
      if (hi > lo) {
        ++walls;
        cut += hi < land_height - 1e-6 || lo > -floor_depth + 1e-6;  // not the whole height: cut
      }
    }
    EXPECT_GT(walls, 0);
    EXPECT_EQ(cut, walls) << "every wall band lies between two cuts";
  }
}

TEST(LandMesh, WallsReachFromTheLandDownToTheFloorWithFlatFaces) {
  const sim::WaterModel model = island_model();
  const std::vector<LandVertex> mesh = build_land_mesh(model);
  float top = -1e9f, bottom = 1e9f;
  for (std::size_t t = 0; t < mesh.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      top = std::max(top, mesh[t + k].position.y);
      bottom = std::min(bottom, mesh[t + k].position.y);
      // Flat: the three vertices of a triangle carry the same normal.
      EXPECT_EQ(mesh[t + k].normal.x, mesh[t].normal.x);
      EXPECT_EQ(mesh[t + k].normal.y, mesh[t].normal.y);
      EXPECT_EQ(mesh[t + k].normal.z, mesh[t].normal.z);
    }
  }
  EXPECT_FLOAT_EQ(top, 1.5f);
  EXPECT_FLOAT_EQ(bottom, -2.0f);
}

// The reflection's land: every wall is cut at y = 0, so the part above the water is whole
// triangles; the reflection keeps those of the walls, no top.
TEST(LandMesh, MirroredWallsAreTheWallsAboveTheRestPlane) {
  const sim::WaterModel model = island_model();
  const std::vector<LandVertex> mesh = build_land_mesh(model);
  std::size_t walls_above = 0, below = 0;
  for (std::size_t t = 0; t < mesh.size(); t += 3) {
    const float y[3] = {mesh[t].position.y, mesh[t + 1].position.y, mesh[t + 2].position.y};
    const float lo = *std::min_element(y, y + 3), hi = *std::max_element(y, y + 3);
    EXPECT_FALSE(lo < 0.0f && hi > 0.0f) << "triangle " << t / 3 << " crosses the water's rest plane";
    if (lo < 0.0f) ++below;
    else if (mesh[t].normal.y == 0.0f) ++walls_above;
  }
  const std::vector<LandVertex> kept = mirrored_walls(mesh);
  EXPECT_EQ(kept.size(), 3 * walls_above);
  EXPECT_GT(walls_above, 0u);
  EXPECT_GT(below, 0u);
  for (const LandVertex& v : kept) {
    EXPECT_GE(v.position.y, 0.0f);
    EXPECT_EQ(v.normal.y, 0.0f);
  }
}

// The sky's box stands on the land's outer edge: the sky starts exactly where the land ends.
TEST(LandMesh, SkyBoxStandsOnTheLandsOuterEdge) {
  const sim::WaterModel model = island_model();
  const std::vector<LandVertex> mesh = build_land_mesh(model);
  float x0 = 1e9f, x1 = -1e9f, z0 = 1e9f, z1 = -1e9f;
  for (const LandVertex& v : mesh) {
    x0 = std::min(x0, v.position.x), x1 = std::max(x1, v.position.x);
    z0 = std::min(z0, v.position.z), z1 = std::max(z1, v.position.z);
  }
  const SkyBox box = sky_box(model);
  EXPECT_FLOAT_EQ(static_cast<float>(box.lo[0]), x0);
  EXPECT_FLOAT_EQ(static_cast<float>(box.hi[0]), x1);
  EXPECT_FLOAT_EQ(static_cast<float>(box.lo[2]), z0);
  EXPECT_FLOAT_EQ(static_cast<float>(box.hi[2]), z1);
  EXPECT_EQ(box.lo[1], 1.5);
  EXPECT_GT(box.hi[1], 1.5 + 10.0);
}

}  // namespace
}  // namespace pond::view
