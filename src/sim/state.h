#pragma once
// The water state in structure-of-arrays form (one array per component, row-major nodes), in grid
// units (world / spacing). SoA lets every SIMD backend load W neighbouring nodes of one component
// with one instruction.
#include <cstddef>
#include <vector>

#include "sim/aligned_buffer.h"
#include "sim/model.h"

namespace pond::sim {

struct WaterState {
  AlignedBuffer<float> x, y, z, vx, vy, vz;

  WaterState() = default;
  explicit WaterState(std::size_t nodes)
      : x(nodes), y(nodes), z(nodes), vx(nodes), vy(nodes), vz(nodes) {}
  std::size_t nodes() const { return x.size(); }
};

// Every node at rest: (j, 0, i) in grid units, zero velocity.
WaterState rest_state(const WaterModel& model);

// The contract's dump layout: float32 (rows, cols, 6) = x, y, z, vx, vy, vz in world units.
std::vector<float> to_world_interleaved(const WaterState& s, const WaterModel& model);
// The inverse, for loading a dump; the caller checks the shape.
WaterState from_world_interleaved(const float* data, const WaterModel& model);

}  // namespace pond::sim
