#include "sim/basin.h"

#include <algorithm>
#include <cmath>

namespace pond::sim {

bool land_cell(const std::vector<std::uint8_t>& kinds, int cols, int i, int j) {
  auto fixed = [&](int r, int c) {
    return kinds[static_cast<std::size_t>(r) * cols + c] == static_cast<std::uint8_t>(NodeKind::fixed);
  };
  return fixed(i, j) && fixed(i, j + 1) && fixed(i + 1, j) && fixed(i + 1, j + 1);
}

std::vector<std::uint32_t> land_runs(const std::vector<std::uint8_t>& kinds, int rows, int cols) {
  const int cell_rows = rows - 1, cell_cols = cols - 1;
  std::vector<std::uint32_t> starts{0}, runs;
  for (int i = 0; i < cell_rows; ++i) {
    for (int j = 0; j < cell_cols;) {
      if (!land_cell(kinds, cols, i, j)) { ++j; continue; }
      int k = j;
      while (k < cell_cols && land_cell(kinds, cols, i, k)) ++k;
      runs.push_back(static_cast<std::uint32_t>(j));
      runs.push_back(static_cast<std::uint32_t>(k));
      j = k;
    }
    starts.push_back(static_cast<std::uint32_t>(runs.size() / 2));
  }
  std::vector<std::uint32_t> out{static_cast<std::uint32_t>(cell_rows)};
  out.insert(out.end(), starts.begin(), starts.end());
  out.insert(out.end(), runs.begin(), runs.end());
  return out;
}

std::optional<std::string> sphere_in_solid(const std::vector<std::uint8_t>& kinds, const GridSpec& g,
                                           const BasinSpec& basin, const std::array<double, 3>& p, double r) {
  const double h = g.spacing, max_x = (g.cols - 1) * h, max_z = (g.rows - 1) * h;
  if (p[1] - r < -basin.floor_depth) return "the pool floor";
  if (p[0] - r < 0.0 || p[0] + r > max_x || p[2] - r < 0.0 || p[2] + r > max_z) return "the rim";
  if (p[1] - r >= basin.land_height) return std::nullopt;
  const int i0 = std::max(0, static_cast<int>(std::floor((p[2] - r) / h)));
  const int i1 = std::min(g.rows - 2, static_cast<int>(std::floor((p[2] + r) / h)));
  const int j0 = std::max(0, static_cast<int>(std::floor((p[0] - r) / h)));
  const int j1 = std::min(g.cols - 2, static_cast<int>(std::floor((p[0] + r) / h)));
  for (int i = i0; i <= i1; ++i)
    for (int j = j0; j <= j1; ++j) {
      if (!land_cell(kinds, g.cols, i, j)) continue;
      const double cx = std::clamp(p[0], j * h, (j + 1) * h), cz = std::clamp(p[2], i * h, (i + 1) * h);
      const double cy = std::min(p[1], basin.land_height);
      const double dx = p[0] - cx, dy = p[1] - cy, dz = p[2] - cz;
      if (dx * dx + dy * dy + dz * dz < r * r)
        return "the land at cell (row " + std::to_string(i) + ", col " + std::to_string(j) + ")";
    }
  return std::nullopt;
}

}  // namespace pond::sim
