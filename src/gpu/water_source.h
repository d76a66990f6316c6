#pragma once
// The solver behind the frame loop, CPU or GPU, and what a frame needs from it after advancing:
//  - the buffers the water vertex shader reads (state: ux | uy | uz arrays of `stride` floats,
//    rows `pitch` nodes apart; normals: one vec4 per node, compact);
//  - the node positions on the CPU, for the LOD builder: the displacements in grid units where they
//    already are (lod::grid_displacements; the builder converts them to world units as it copies).
// GPU: the solver's own buffers (no copy for drawing); the normals pass runs on the GPU and the three
//      displacement arrays are read in place where the state's memory is host-readable (lavapipe),
//      else copied into a host-readable buffer (about 0.8 MB at 257^2). A frame's substeps,
//      normals and copy are one submission (advance_and_prepare).
// CPU: the state and the CPU normals are written into the frame slot's host-visible buffers
//      (per slot, so a frame in flight keeps reading its own).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/frame_loop.h"
#include "gpu/gpu_solver.h"
#include "lod/node_positions.h"
#include "sim/cpu_solver.h"

namespace pond::gpu {

class WaterSource {
 public:
  WaterSource(const Context& ctx, const sim::WaterModel& model, const SolverChoice& choice, std::uint32_t slots);

  void advance(std::int64_t steps);

  struct DrawBuffers {
    const Buffer* state;
    const Buffer* normals;
    std::uint32_t stride;  // floats between the state's component arrays
    std::uint32_t pitch;   // nodes between the state's rows: the GPU solver's pitch, or cols (CPU)
  };
  // Normals of the current state, positions made visible to the CPU, and the buffers frame slot
  // `slot` draws from.
  DrawBuffers prepare(std::uint32_t slot) { return advance_and_prepare(0, slot); }
  // advance(steps) then prepare(slot); on the GPU all of it is one submission and one wait.
  DrawBuffers advance_and_prepare(std::int64_t steps, std::uint32_t slot);
  // Positions of the state prepare() last saw, as a view of its displacements: valid until the
  // next advance, set_state or prepare.
  lod::NodePositions positions() const;

  sim::WaterState state() const;
  std::int64_t steps_done() const;
  void set_state(const sim::WaterState& state, std::int64_t steps_done);

 private:
  const Context& ctx_;
  const sim::WaterModel& model_;
  std::optional<GpuSolver> gpu_;
  std::optional<sim::CpuSolver> cpu_;
  Buffer readback_;  // GPU, when the state is not host-readable: the displacements, copied
  std::vector<Buffer> slot_state_, slot_normals_;  // CPU: per slot
  std::array<const float*, 3> displacements_{};  // ux, uy, uz of the state prepare() last saw
  std::size_t displacements_pitch_ = 0;           // nodes between their rows
};

}  // namespace pond::gpu
