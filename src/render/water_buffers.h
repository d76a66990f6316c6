#pragma once
// The GPU buffers a frame draws the water and the bodies from (render/water_source.h makes them
// ready): the solver's own, or a CPU solver's state copied into the frame slot's.
#include <cstdint>

#include "gpu/buffer.h"

namespace pond::render {

struct WaterBuffers {
  const gpu::Buffer* state;    // ux | uy | uz arrays of `stride` floats, rows `pitch` nodes apart
  const gpu::Buffer* normals;  // one vec4 per node, compact
  const gpu::Buffer* bodies;   // sim::BodyState per body; null without bodies
  std::uint32_t stride;
  std::uint32_t pitch;
};

}  // namespace pond::render
