#include "view/land_mesh.h"

#include <algorithm>

#include "sim/basin.h"

namespace pond::view {
namespace {

using shared::water_render::vec4;

struct P {
  double x, y, z;
};

// Two triangles a-b-c, a-c-d, all with the normal n.
void quad(std::vector<LandVertex>& out, P a, P b, P c, P d, P n) {
  const vec4 normal{static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z), 0.0f};
  for (const P& p : {a, b, c, a, c, d})
    out.push_back({vec4{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), 1.0f}, normal});
}

// A wall quad from the top edge a-b at land height down to the floor, cut at the heights where
// the wetness ramp bends (shared/water_render.h kLandWetAtRest), so per-vertex lighting is exact,
// and at the water's rest plane y = 0, so mirrored_walls() can keep the part the reflection mirrors.
void wall(std::vector<LandVertex>& out, P a, P b, double top, double bottom, P n) {
  std::vector<double> cuts = {top};
  for (const double y : {shared::water_render::kLandWetAtRest * top, 0.0, (shared::water_render::kLandWetAtRest - 1.0) * top})
    if (y < top && y > bottom) cuts.push_back(y);
  cuts.push_back(bottom);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double y0 = cuts[k], y1 = cuts[k + 1];
    quad(out, {a.x, y0, a.z}, {b.x, y0, b.z}, {b.x, y1, b.z}, {a.x, y1, a.z}, n);
  }
}

}  // namespace

std::vector<LandVertex> build_land_mesh(const sim::WaterModel& model) {
  const int rows = model.rows, cols = model.cols;
  const double h = model.spacing, top = model.basin.land_height, bottom = -model.basin.floor_depth;
  // land[i][j]: cell (i, j) spans nodes i..i+1, j..j+1.
  const int cr = rows - 1, cc = cols - 1;
  std::vector<std::uint8_t> land(static_cast<std::size_t>(cr) * cc);
  for (int i = 0; i < cr; ++i)
    for (int j = 0; j < cc; ++j)
      land[static_cast<std::size_t>(i) * cc + j] = sim::land_cell(model.kinds, cols, i, j);
  auto is_land = [&](int i, int j) { return land[static_cast<std::size_t>(i) * cc + j] != 0; };

  std::vector<LandVertex> out;
  for (int i = 0; i < cr; ++i) {
    const double z0 = i * h, z1 = (i + 1) * h;
    for (int j = 0; j < cc;) {
      if (!is_land(i, j)) { ++j; continue; }
      int k = j;
      while (k < cc && is_land(i, k)) ++k;  // a run of land cells [j, k): one top quad
      quad(out, {j * h, top, z0}, {j * h, top, z1}, {k * h, top, z1}, {k * h, top, z0}, {0, 1, 0});
      j = k;
    }
    // Walls where land meets water, facing the water.
    for (int j = 0; j < cc; ++j) {
      if (!is_land(i, j)) continue;
      const double x0 = j * h, x1 = (j + 1) * h;
      if (i > 0 && !is_land(i - 1, j)) wall(out, {x0, top, z0}, {x1, top, z0}, top, bottom, {0, 0, -1});
      if (i + 1 < cr && !is_land(i + 1, j)) wall(out, {x0, top, z1}, {x1, top, z1}, top, bottom, {0, 0, 1});
      if (j > 0 && !is_land(i, j - 1)) wall(out, {x0, top, z0}, {x0, top, z1}, top, bottom, {-1, 0, 0});
      if (j + 1 < cc && !is_land(i, j + 1)) wall(out, {x1, top, z0}, {x1, top, z1}, top, bottom, {1, 0, 0});
    }
  }

  // The rim: four inward walls and the land around, out to 4x the pond's size (sky_box: the same).
  const double w = cc * h, d = cr * h, m = 4.0 * std::max(w, d);
  wall(out, {0, top, 0}, {w, top, 0}, top, bottom, {0, 0, 1});
  wall(out, {0, top, d}, {w, top, d}, top, bottom, {0, 0, -1});
  wall(out, {0, top, 0}, {0, top, d}, top, bottom, {1, 0, 0});
  wall(out, {w, top, 0}, {w, top, d}, top, bottom, {-1, 0, 0});
  quad(out, {-m, top, -m}, {w + m, top, -m}, {w + m, top, 0}, {-m, top, 0}, {0, 1, 0});
  quad(out, {-m, top, d}, {w + m, top, d}, {w + m, top, d + m}, {-m, top, d + m}, {0, 1, 0});
  quad(out, {-m, top, 0}, {0, top, 0}, {0, top, d}, {-m, top, d}, {0, 1, 0});
  quad(out, {w, top, 0}, {w + m, top, 0}, {w + m, top, d}, {w, top, d}, {0, 1, 0});
  return out;
}

SkyBox sky_box(const sim::WaterModel& model) {
  const double land_height = model.basin.land_height, h = model.spacing, w = (model.cols - 1) * h, d = (model.rows - 1) * h, m = 4.0 * std::max(w, d);
  return {{-m, land_height, -m}, {w + m, land_height + 1.5 * std::max(w, d), d + m}};
}

std::vector<LandVertex> mirrored_walls(const std::vector<LandVertex>& mesh) {
  std::vector<LandVertex> out;
  for (std::size_t t = 0; t + 2 < mesh.size(); t += 3)
    if (mesh[t].normal.y == 0.0f && mesh[t].position.y >= 0.0f && mesh[t + 1].position.y >= 0.0f &&
        mesh[t + 2].position.y >= 0.0f)
      out.insert(out.end(), mesh.begin() + static_cast<std::ptrdiff_t>(t), mesh.begin() + static_cast<std::ptrdiff_t>(t + 3));
  return out;
}

std::vector<LandVertex> submerged_walls(const std::vector<LandVertex>& mesh, const sim::WaterModel& model) {
  const float x_max = static_cast<float>(model.cols - 1) * model.spacing;
  const float z_max = static_cast<float>(model.rows - 1) * model.spacing;
  const float eps = static_cast<float>(1e-4 * model.spacing);
  // On the rim: every corner on the same border line of the pool.
  const auto on_rim = [&](const LandVertex* v) {
    const auto all = [&](auto on_line) { return on_line(v[0]) && on_line(v[1]) && on_line(v[2]); };
    return all([&](const LandVertex& p) { return p.position.x <= eps; }) ||
           all([&](const LandVertex& p) { return p.position.x >= x_max - eps; }) ||
           all([&](const LandVertex& p) { return p.position.z <= eps; }) ||
           all([&](const LandVertex& p) { return p.position.z >= z_max - eps; });
  };
  std::vector<LandVertex> out;
  for (std::size_t t = 0; t + 2 < mesh.size(); t += 3)
    if (mesh[t].normal.y == 0.0f && mesh[t].position.y <= 0.0f && mesh[t + 1].position.y <= 0.0f &&
        mesh[t + 2].position.y <= 0.0f && !on_rim(&mesh[t]))
      out.insert(out.end(), mesh.begin() + static_cast<std::ptrdiff_t>(t), mesh.begin() + static_cast<std::ptrdiff_t>(t + 3));
  return out;
}

std::vector<ShadowCaster> touching_boxes(const std::vector<LandVertex>& triangles) {
  std::vector<ShadowCaster> boxes;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    ShadowCaster b{{triangles[t].position.x, triangles[t].position.y, triangles[t].position.z},
                   {triangles[t].position.x, triangles[t].position.y, triangles[t].position.z}};
    for (std::size_t v = t + 1; v < t + 3; ++v) {
      const float p[3] = {triangles[v].position.x, triangles[v].position.y, triangles[v].position.z};
      for (int k = 0; k < 3; ++k) b.lo[k] = std::min(b.lo[k], p[k]), b.hi[k] = std::max(b.hi[k], p[k]);
    }
    boxes.push_back(b);
  }
  const auto touch = [](const ShadowCaster& a, const ShadowCaster& b) {
    for (int k = 0; k < 3; ++k)
      if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
    return true;
  };
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t i = 0; i < boxes.size(); ++i)
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        if (touch(boxes[i], boxes[j])) {
          for (int k = 0; k < 3; ++k)
            boxes[i].lo[k] = std::min(boxes[i].lo[k], boxes[j].lo[k]), boxes[i].hi[k] = std::max(boxes[i].hi[k], boxes[j].hi[k]);
          boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(j));
          merged = true;
          --j;
        }
  }
  return boxes;
}

}  // namespace pond::view
