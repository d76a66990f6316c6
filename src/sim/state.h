#pragma once
// The water state in structure-of-arrays form (one array per component, row-major nodes), in grid
// units (world / spacing). SoA lets every SIMD backend load W neighbouring nodes of one component
// with one instruction.
//
// Positions are stored as displacements u from the rest position (j, 0, i), not as absolute
// coordinates: a float near 1000 has an ulp of 6e-5, which on a large grid would quantize the
// horizontal motion and add noise to spring strains of that order; a displacement near 0 keeps full
// precision, and the rounding of the physics is the same everywhere on the grid.
#include <cstddef>
#include <vector>

#include "sim/aligned_buffer.h"
#include "sim/model.h"

namespace pond::sim {

struct WaterState {
  AlignedBuffer<float> ux, uy, uz, vx, vy, vz;
  std::vector<BodyState> bodies;  // one per body of the model, grid units (sim/bodies.h)

  WaterState() = default;
  explicit WaterState(std::size_t nodes)
      : ux(nodes), uy(nodes), uz(nodes), vx(nodes), vy(nodes), vz(nodes) {}
  std::size_t nodes() const { return ux.size(); }
};

// Every node at rest: zero displacement, zero velocity; the bodies where the scene puts them.
WaterState rest_state(const WaterModel& model);

// The contract's dump layout: float32 (rows, cols, 6) = x, y, z, vx, vy, vz in world units.
std::vector<float> to_world_interleaved(const WaterState& s, const WaterModel& model);
// The inverse, for loading a dump; the caller checks the shape.
WaterState from_world_interleaved(const float* data, const WaterModel& model);

}  // namespace pond::sim
