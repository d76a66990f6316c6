#include "sim/normals.h"

#include <algorithm>

#include "shared/exact_math.h"

namespace pond::sim {

Normals compute_normals(const WaterState& s, const WaterModel& m) {
  return compute_normals(HostDisplacements{s.ux.data(), s.uy.data(), s.uz.data(), static_cast<std::size_t>(m.cols)}, m);
}

Normals compute_normals(const HostDisplacements& s, const WaterModel& m) {
  Normals n;
  n.x.resize(m.nodes());
  n.y.resize(m.nodes());
  n.z.resize(m.nodes());
  const int R = m.rows, C = m.cols;
  auto at = [&s](int i, int j) { return static_cast<std::size_t>(i) * s.pitch + static_cast<std::size_t>(j); };
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) {
      const int i1 = std::min(i + 1, R - 1), i0 = std::max(i - 1, 0);
      const int j1 = std::min(j + 1, C - 1), j0 = std::max(j - 1, 0);
      const std::size_t up = at(i1, j), down = at(i0, j), right = at(i, j1), left = at(i, j0);
      // Position differences = displacement differences + the rest offset (i1 - i0 or j1 - j0).
      const float ax = s.ux[up] - s.ux[down], ay = s.uy[up] - s.uy[down],
                  az = (s.uz[up] - s.uz[down]) + static_cast<float>(i1 - i0);
      const float bx = (s.ux[right] - s.ux[left]) + static_cast<float>(j1 - j0),
                  by = s.uy[right] - s.uy[left], bz = s.uz[right] - s.uz[left];
      const float cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
      const float l2 = (cx * cx + cy * cy) + cz * cz;
      const float r = l2 > 0.0f ? shared::rsqrt_exact(l2, shared::kRsqrtStepsExact) : 0.0f;
      const std::size_t k = static_cast<std::size_t>(i) * static_cast<std::size_t>(C) + static_cast<std::size_t>(j);
      n.x[k] = cx * r;
      n.y[k] = l2 > 0.0f ? cy * r : 1.0f;
      n.z[k] = cz * r;
    }
  return n;
}

}  // namespace pond::sim
