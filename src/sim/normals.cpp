#include "sim/normals.h"

#include <algorithm>

#include "shared/exact_math.h"

namespace pond::sim {

Normals compute_normals(const WaterState& s, const WaterModel& m) {
  Normals n;
  n.x.resize(m.nodes());
  n.y.resize(m.nodes());
  n.z.resize(m.nodes());
  const int R = m.rows, C = m.cols;
  auto at = [C](int i, int j) { return static_cast<std::size_t>(i) * C + j; };
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) {
      const std::size_t up = at(std::min(i + 1, R - 1), j), down = at(std::max(i - 1, 0), j);
      const std::size_t right = at(i, std::min(j + 1, C - 1)), left = at(i, std::max(j - 1, 0));
      const float ax = s.x[up] - s.x[down], ay = s.y[up] - s.y[down], az = s.z[up] - s.z[down];
      const float bx = s.x[right] - s.x[left], by = s.y[right] - s.y[left], bz = s.z[right] - s.z[left];
      const float cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
      const float l2 = (cx * cx + cy * cy) + cz * cz;
      const float r = l2 > 0.0f ? shared::rsqrt_exact(l2, shared::kRsqrtStepsExact) : 0.0f;
      const std::size_t k = at(i, j);
      n.x[k] = cx * r;
      n.y[k] = l2 > 0.0f ? cy * r : 1.0f;
      n.z[k] = cz * r;
    }
  return n;
}

}  // namespace pond::sim
