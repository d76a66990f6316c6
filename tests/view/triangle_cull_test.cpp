// view/triangle_cull.h: which triangles each draw gets, against an identity view (clip = world,
// w = 1: x, y in [-1, 1] and depth z in [0, 1] are inside) on a 100 x 100 pixel target.
#include "view/triangle_cull.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

namespace pond::view {
namespace {

constexpr std::array<float, 16> kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Triangles given by their corners; vertex k of triangle t is 3t + k.
struct Mesh {
  std::vector<float> x, y, z;
  std::vector<std::uint32_t> triangles;
  void add(std::array<std::array<float, 3>, 3> corners) {
    for (const auto& c : corners) {
      triangles.push_back(static_cast<std::uint32_t>(x.size()));
      x.push_back(c[0]), y.push_back(c[1]), z.push_back(c[2]);
    }
  }
  CulledMesh cull(std::span<const PixelRect> rects = {}) const {
    CulledMesh out;
    cull_triangles(triangles, {x, y, z}, kIdentity, 100, 100, rects, out);
    return out;
  }
};

// The triangles (by number) of one range's part: [first, first + count).
std::vector<std::uint32_t> triangles_of(const CulledMesh& m, std::uint32_t first, std::uint32_t count) {
  std::vector<std::uint32_t> t;
  for (std::uint32_t k = first; k < first + count; k += 3) t.push_back(m.indices[k] / 3);
  return t;
}

TEST(TriangleCull, InsideFirstThenAcrossAndWhollyOutsideLeftOut) {
  Mesh m;
  m.add({{{-2.0f, 0.0f, 0.5f}, {-1.5f, 0.5f, 0.5f}, {-3.0f, 0.2f, 0.5f}}});  // 0: left of x = -1
  m.add({{{-0.5f, -0.5f, 0.5f}, {0.5f, -0.5f, 0.5f}, {0.0f, 0.5f, 0.5f}}});  // 1: inside
  m.add({{{-0.5f, 0.0f, -0.5f}, {0.5f, 0.0f, 0.5f}, {0.0f, 0.5f, 0.5f}}});   // 2: across the near plane
  m.add({{{0.0f, 0.0f, -1.0f}, {0.1f, 0.0f, -0.5f}, {0.0f, 0.1f, -2.0f}}});  // 3: wholly in front of it
  m.add({{{-2.0f, 0.0f, 0.5f}, {2.0f, 0.0f, 0.5f}, {0.0f, 0.5f, 0.5f}}});    // 4: across x = -1 and x = 1
  m.add({{{0.2f, 0.2f, 0.2f}, {0.3f, 0.2f, 0.2f}, {0.2f, 0.3f, 0.2f}}});     // 5: inside
  const CulledMesh c = m.cull();
  EXPECT_EQ(c.whole.first, 0u);
  EXPECT_EQ(triangles_of(c, 0, c.whole.inside), (std::vector<std::uint32_t>{1, 5}));
  EXPECT_EQ(triangles_of(c, c.whole.inside, c.whole.across), (std::vector<std::uint32_t>{2, 4}));
  EXPECT_EQ(c.indices.size(), 12u);
}

TEST(TriangleCull, ACornerOnAPlaneIsNeitherLeftOutNorCalledInside) {
  Mesh m;
  m.add({{{-1.0f, 0.0f, 0.5f}, {-1.0f, 0.5f, 0.5f}, {-1.0f, 0.2f, 0.5f}}});  // in the plane x = -1
  m.add({{{-1.0f, 0.0f, 0.5f}, {0.5f, 0.5f, 0.5f}, {0.0f, 0.2f, 0.5f}}});    // one corner on it
  const CulledMesh c = m.cull();
  EXPECT_EQ(c.whole.inside, 0u);
  EXPECT_EQ(c.whole.across, 6u);
}

TEST(TriangleCull, ARectangleGetsTheTrianglesThatCanReachItAndEveryOneAcross) {
  Mesh m;
  m.add({{{-0.9f, -0.9f, 0.5f}, {-0.7f, -0.9f, 0.5f}, {-0.9f, -0.7f, 0.5f}}});  // 0: pixels 5..15, 5..15
  m.add({{{0.5f, 0.5f, 0.5f}, {0.9f, 0.5f, 0.5f}, {0.5f, 0.9f, 0.5f}}});        // 1: pixels 75..95
  m.add({{{-0.5f, 0.0f, -0.5f}, {0.5f, 0.0f, 0.5f}, {0.0f, 0.5f, 0.5f}}});      // 2: across
  m.add({{{-0.1f, -0.1f, 0.5f}, {0.1f, -0.1f, 0.5f}, {0.0f, 0.1f, 0.5f}}});     // 3: pixels 45..55
  const PixelRect rects[] = {{0, 0, 20, 20}, {58, 58, 72, 72}, {40, 50, 60, 60}};
  const CulledMesh c = m.cull(rects);
  ASSERT_EQ(c.rects.size(), 3u);
  auto in = [&](const IndexRange& r) {
    std::vector<std::uint32_t> t = triangles_of(c, r.first, r.inside + r.across);
    std::sort(t.begin(), t.end());
    return t;
  };
  EXPECT_EQ(in(c.whole), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(in(c.rects[0]), (std::vector<std::uint32_t>{0, 2}));
  EXPECT_EQ(in(c.rects[1]), (std::vector<std::uint32_t>{2}));  // between triangles 3 and 1, 3 pixels off each
  EXPECT_EQ(in(c.rects[2]), (std::vector<std::uint32_t>{2, 3}));
  EXPECT_EQ(c.rects[1].inside, 0u);
}

}  // namespace
}  // namespace pond::view
