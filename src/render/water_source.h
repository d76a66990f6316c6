#pragma once
// What a frame needs from the session's solver (CPU or GPU) after advancing:
//  - the buffers the water vertex shader reads (state: ux | uy | uz arrays of `stride` floats,
//    rows `pitch` nodes apart; normals: one vec4 per node, compact);
//  - the node positions on the CPU, for the LOD builder: the displacements in grid units where they
//    already are (lod::grid_displacements; the builder converts them to world units as it copies).
// GPU: the solver's own buffers (no copy for drawing); the normals pass runs on the GPU and the three
//      displacement arrays are read in place where the state's memory is host-readable (lavapipe),
//      else copied into a host-readable buffer (about 0.8 MB at 257^2). A frame's substeps,
//      normals and copy are one submission.
// CPU: the state and the CPU normals are written into the frame slot's host-visible buffers
//      (per slot, so a frame in flight keeps reading its own).
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "gpu/buffer.h"
#include "render/frame_loop.h"
#include "gpu/gpu_solver.h"
#include "lod/node_positions.h"
#include "sim/cpu_solver.h"

namespace pond::render {

class WaterSource {
 public:
  // For `solver` (a gpu::GpuSolver or a sim::CpuSolver), which must outlive this.
  WaterSource(const gpu::Context& ctx, sim::Solver& solver, std::uint32_t slots);

  struct DrawBuffers {
    const gpu::Buffer* state;
    const gpu::Buffer* normals;
    std::uint32_t stride;  // floats between the state's component arrays
    std::uint32_t pitch;   // nodes between the state's rows: the GPU solver's pitch, or cols (CPU)
  };
  // Normals of the current state, positions made visible to the CPU, and the buffers frame slot
  // `slot` draws from.
  DrawBuffers prepare(std::uint32_t slot);
  // Positions of the state prepare() last saw, as a view of its displacements: valid until the
  // solver's next step or state change, or the next prepare.
  lod::NodePositions positions() const;

 private:
  const gpu::Context& ctx_;
  const sim::WaterModel& model_;
  gpu::GpuSolver* gpu_ = nullptr;        // one of the two
  const sim::CpuSolver* cpu_ = nullptr;
  gpu::Buffer readback_;  // GPU, when the state is not host-readable: the displacements, copied
  std::vector<gpu::Buffer> slot_state_, slot_normals_;  // CPU: per slot
  std::array<const float*, 3> displacements_{};  // ux, uy, uz of the state prepare() last saw
  std::size_t displacements_pitch_ = 0;           // nodes between their rows
};

}  // namespace pond::render
