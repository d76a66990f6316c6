#include "sim/state.h"

namespace pond::sim {

WaterState rest_state(const WaterModel& m) {
  WaterState s(m.nodes());
  for (int i = 0; i < m.rows; ++i)
    for (int j = 0; j < m.cols; ++j) {
      const std::size_t n = static_cast<std::size_t>(i) * m.cols + j;
      s.x[n] = static_cast<float>(j);
      s.z[n] = static_cast<float>(i);
    }
  return s;
}

std::vector<float> to_world_interleaved(const WaterState& s, const WaterModel& m) {
  std::vector<float> out(s.nodes() * 6);
  const float h = m.spacing;
  for (std::size_t n = 0; n < s.nodes(); ++n) {
    float* o = &out[n * 6];
    o[0] = s.x[n] * h;
    o[1] = s.y[n] * h;
    o[2] = s.z[n] * h;
    o[3] = s.vx[n] * h;
    o[4] = s.vy[n] * h;
    o[5] = s.vz[n] * h;
  }
  return out;
}

WaterState from_world_interleaved(const float* d, const WaterModel& m) {
  WaterState s(m.nodes());
  const float inv_h = 1.0f / m.spacing;
  for (std::size_t n = 0; n < s.nodes(); ++n) {
    const float* p = d + n * 6;
    s.x[n] = p[0] * inv_h;
    s.y[n] = p[1] * inv_h;
    s.z[n] = p[2] * inv_h;
    s.vx[n] = p[3] * inv_h;
    s.vy[n] = p[4] * inv_h;
    s.vz[n] = p[5] * inv_h;
  }
  return s;
}

}  // namespace pond::sim
