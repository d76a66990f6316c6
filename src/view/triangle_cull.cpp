#include "view/triangle_cull.h"

#include <algorithm>
#include <cmath>

namespace pond::view {
namespace {

// A corner's side of each plane of the view volume (bits: x < -w, x > w, y < -w, y > w, z < 0,
// z > w), each tested with a relative margin so a corner on a plane counts as inside it (for the
// left-out test) and as outside it (for the inside test) whatever the device's rounding.
constexpr float kMargin = 1e-4f;

struct Corner {
  float x, y, z, w;
};

Corner clip(const std::array<float, 16>& m, float x, float y, float z) {
  return {m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13],
          m[2] * x + m[6] * y + m[10] * z + m[14], m[3] * x + m[7] * y + m[11] * z + m[15]};
}

// Planes the corner is surely outside of.
unsigned outside(const Corner& c) {
  const float e = kMargin * std::abs(c.w);
  return (c.x < -c.w - e ? 1u : 0u) | (c.x > c.w + e ? 2u : 0u) | (c.y < -c.w - e ? 4u : 0u) |
         (c.y > c.w + e ? 8u : 0u) | (c.z < -e ? 16u : 0u) | (c.z > c.w + e ? 32u : 0u);
}

// Whether the corner is surely inside every plane.
bool inside(const Corner& c) {
  const float e = kMargin * std::abs(c.w);
  return c.w > 0.0f && c.x >= -c.w + e && c.x <= c.w - e && c.y >= -c.w + e && c.y <= c.w - e && c.z >= e &&
         c.z <= c.w - e;
}

}  // namespace

void cull_triangles(std::span<const std::uint32_t> triangles, const MeshPositions& positions,
                    const std::array<float, 16>& view_proj, int width, int height, std::span<const PixelRect> rects,
                    CulledMesh& out) {
  // Pass 1: each kept triangle, inside ones with their pixel bounding boxes.
  using Kept = CulledMesh::Kept;
  std::vector<Kept>& kept = out.kept;
  kept.clear();
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    Corner c[3];
    unsigned all_out = ~0u;
    bool all_in = true;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = triangles[t + static_cast<std::size_t>(k)];
      c[k] = clip(view_proj, positions.x[v], positions.y[v], positions.z[v]);
      all_out &= outside(c[k]);
      all_in = all_in && inside(c[k]);
    }
    if (all_out != 0) continue;  // wholly beyond one plane: not drawn by any draw
    Kept k{static_cast<std::uint32_t>(t), all_in, 0, 0, 0, 0};
    if (all_in) {
      k.x0 = k.y0 = INFINITY;
      k.x1 = k.y1 = -INFINITY;
      for (const Corner& p : c) {
        const float px = (p.x / p.w * 0.5f + 0.5f) * static_cast<float>(width);
        const float py = (p.y / p.w * 0.5f + 0.5f) * static_cast<float>(height);
        k.x0 = std::min(k.x0, px), k.x1 = std::max(k.x1, px);
        k.y0 = std::min(k.y0, py), k.y1 = std::max(k.y1, py);
      }
    }
    kept.push_back(k);
  }

  // Pass 2: the lists, inside triangles first.
  out.indices.clear();
  out.rects.clear();
  auto emit = [&](auto wanted) {
    IndexRange r{static_cast<std::uint32_t>(out.indices.size()), 0, 0};
    for (const bool inside_pass : {true, false})
      for (const Kept& k : kept)
        if (k.inside == inside_pass && wanted(k)) {
          out.indices.insert(out.indices.end(), triangles.begin() + k.first, triangles.begin() + k.first + 3);
          (inside_pass ? r.inside : r.across) += 3;
        }
    return r;
  };
  out.whole = emit([](const Kept&) { return true; });
  for (const PixelRect& rect : rects)
    out.rects.push_back(emit([&](const Kept& k) {
      return !k.inside || (k.x1 + 1.0f >= static_cast<float>(rect.x0) && k.x0 - 1.0f <= static_cast<float>(rect.x1) &&
                           k.y1 + 1.0f >= static_cast<float>(rect.y0) && k.y0 - 1.0f <= static_cast<float>(rect.y1));
    }));
}

}  // namespace pond::view
