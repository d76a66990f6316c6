#include "sim/state.h"

namespace pond::sim {

WaterState rest_state(const WaterModel& m) {
  WaterState s(m.nodes());
  for (const BodyModel& b : m.bodies) s.bodies.push_back(b.initial);
  return s;
}

std::vector<float> to_world_interleaved(const WaterState& s, const WaterModel& m) {
  std::vector<float> out(s.nodes() * 6);
  const float h = m.spacing;
  for (std::size_t n = 0; n < s.nodes(); ++n) {
    float* o = &out[n * 6];
    const auto i = static_cast<float>(n / static_cast<std::size_t>(m.cols));
    const auto j = static_cast<float>(n % static_cast<std::size_t>(m.cols));
    o[0] = (j + s.ux[n]) * h;
    o[1] = s.uy[n] * h;
    o[2] = (i + s.uz[n]) * h;
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
    const auto i = static_cast<float>(n / static_cast<std::size_t>(m.cols));
    const auto j = static_cast<float>(n % static_cast<std::size_t>(m.cols));
    s.ux[n] = p[0] * inv_h - j;
    s.uy[n] = p[1] * inv_h;
    s.uz[n] = p[2] * inv_h - i;
    s.vx[n] = p[3] * inv_h;
    s.vy[n] = p[4] * inv_h;
    s.vz[n] = p[5] * inv_h;
  }
  return s;
}

}  // namespace pond::sim
