#pragma once
// What a frame draws the water and the bodies from, whichever solver the session holds (never cast:
// the GPU solver is found through the gpu::GpuSolvers that made it):
//  - the GPU solver: its own buffers, as its last submission left them (the state, the normals it
//    computed, the bodies' states); nothing is copied for drawing;
//  - a CPU solver: the state's displacements, their normals (computed here) and the bodies' states
//    written into the frame slot's host-visible buffers (per slot: a frame in flight keeps its own).
// The LOD's positions are the solver's displacements() on the host: the GPU solver waits there for
// its last submission (in a frame, the one wait) and hands over its copy, or the state in place
// where the state's memory is host-readable (lavapipe). Its copy holds only the nodes the last
// frame's LOD read; the LOD brings any others it needs (lod/node_positions.h: NodeFetch).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/gpu_solvers.h"
#include "lod/node_positions.h"
#include "render/frame_constants.h"
#include "sim/session.h"

namespace pond::render {

class WaterSource : public lod::NodeFetch {
 public:
  // `gpu`: what made the session's GPU solvers (null: the session only ever holds CPU solvers).
  // Both must outlive this.
  WaterSource(const gpu::Context& ctx, const sim::Session& session, const gpu::GpuSolvers* gpu);

  struct DrawBuffers {
    const gpu::Buffer* state;    // ux | uy | uz arrays of `stride` floats, rows `pitch` nodes apart
    const gpu::Buffer* normals;  // one vec4 per node, compact
    const gpu::Buffer* bodies;   // sim::BodyState per body; null without bodies
    std::uint32_t stride;
    std::uint32_t pitch;
  };
  // The state on the host, as the session's solver last changed it: the GPU solver waits here for
  // its last submission (which also finishes every frame submitted before it).
  void sync() {
    displacements_ = session_.solver().displacements();
    tiles_ = session_.solver().tile_bounds();
  }
  // The buffers frame slot `slot` (finished) draws the state sync() saw from.
  DrawBuffers prepare(std::uint32_t slot);
  // The positions of the state prepare() last saw, for the LOD builder: valid until the session
  // changes the state.
  lod::NodePositions positions() const;
  // Their tile bounds (sim/solver.h), when the session's solver keeps them; else empty.
  std::span<const shared::TileBounds> tile_bounds() const { return tiles_; }
  // The GPU solver reads back only the nodes the LOD reads (sim/solver.h: keep_on_host): which the
  // host holds, bringing more, and which to copy after the next submissions (nullopt: all).
  bool holds(const core::GridWindow& w) const override { return session_.solver().holds_on_host(w); }
  void bring(std::span<const core::GridWindow> windows) const override { session_.solver().bring_to_host(windows); }
  // `lod_reads` (VisibleGeometry::lod_reads) where the whole copy would be larger than
  // kReadBackInPartsFrom; below that, every node (a few extra waits would cost more than the copy).
  void keep_on_host(std::optional<std::vector<core::GridWindow>> lod_reads) const;
  static constexpr std::size_t kReadBackInPartsFrom = std::size_t{4} << 20;  // bytes of ux | uy | uz

 private:
  // The session's solver when it is the GPU solver, else null.
  const gpu::GpuSolver* session_gpu() const;

  const gpu::Context& ctx_;
  const sim::Session& session_;
  const gpu::GpuSolvers* gpu_;
  struct SlotBuffers {
    gpu::Buffer state, normals, bodies;
  };
  std::vector<SlotBuffers> cpu_;  // CPU solver: per slot, made on first use
  sim::HostDisplacements displacements_{};
  std::span<const shared::TileBounds> tiles_;
};

}  // namespace pond::render
