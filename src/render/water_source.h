#pragma once
// What a frame draws the water and the bodies from, whichever solver the session holds (never cast:
// the GPU solver is found through the gpu::GpuSolvers that made it):
//  - the GPU solver: its own buffers, as its last submission left them (the state, the normals it
//    computed, the bodies' states); nothing is copied for drawing;
//  - a CPU solver: the state's displacements, their normals (computed here) and the bodies' states
//    written into the frame slot's host-visible buffers (per slot: a frame in flight keeps its own).
// Every read of the solver is here, and waits in sight: sync() is the frame's one wait (for the
// last submission), which leaves the displacements, their tile bounds and the bodies on the host;
// the LOD's positions are those displacements (the GPU solver's copy, or the state in place where
// its memory is host-readable: lavapipe). The copy holds only the nodes the frame planned to read
// (keep_on_host(): the last frame's LOD reads); the LOD brings any others it needs through
// bring_and_wait(), a wait of its own (lod/node_positions.h: NodeFetch).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/gpu_solvers.h"
#include "lod/node_positions.h"
#include "render/frame_constants.h"
#include "render/water_buffers.h"
#include "sim/session.h"

namespace pond::render {

class WaterSource : public lod::NodeFetch {
 public:
  // `gpu`: what made the session's GPU solvers (null: the session only ever holds CPU solvers).
  // Both must outlive this.
  WaterSource(const gpu::Context& ctx, sim::Session& session, const gpu::GpuSolvers* gpu);

  using DrawBuffers = WaterBuffers;
  // The state on the host, as the session's solver last changed it: the GPU solver waits here for
  // its last submission (which also finishes every frame submitted before it).
  void sync();
  // The buffers frame slot `slot` (finished) draws the state sync() saw from.
  DrawBuffers prepare(std::uint32_t slot);
  // The positions of the state prepare() last saw, for the LOD builder: valid until the session
  // changes the state. Without a fetch: the frame gives the LOD fetch() where it may bring nodes.
  lod::NodePositions positions() const;
  // What brings the nodes the host lacks (this, with the GPU solver), or null where every node is
  // on the host (a CPU solver).
  lod::NodeFetch* fetch() { return session_gpu() ? this : nullptr; }
  // Their tile bounds (sim/solver.h), when the session's solver keeps them; else empty.
  std::span<const shared::TileBounds> tile_bounds() const { return tiles_; }
  // The bodies' states sync() saw (grid units), what the frame draws them at.
  std::span<const sim::BodyState> bodies() const { return bodies_; }
  // The GPU solver reads back only the nodes the LOD reads (sim/solver.h: keep_on_host): which the
  // host holds, bringing more (a wait), and which to copy after the next submissions (nullopt: all).
  bool holds(const core::GridWindow& w) override { return session_.reader().holds_on_host(w); }
  void bring_and_wait(std::span<const core::GridWindow> windows) override { session_.reader().bring_to_host(windows); }
  // `lod_reads` (VisibleGeometry::lod_reads) where the whole copy would be larger than
  // kReadBackInPartsFrom; below that, every node (a few extra waits would cost more than the copy).
  void keep_on_host(std::optional<std::vector<core::GridWindow>> lod_reads);
  static constexpr std::size_t kReadBackInPartsFrom = std::size_t{4} << 20;  // bytes of ux | uy | uz

 private:
  // The session's solver when it is the GPU solver, else null.
  const gpu::GpuSolver* session_gpu() const;

  const gpu::Context& ctx_;
  sim::Session& session_;
  const gpu::GpuSolvers* gpu_;
  struct SlotBuffers {
    gpu::Buffer state, normals, bodies;
  };
  std::vector<SlotBuffers> cpu_;  // CPU solver: per slot, made on first use
  sim::HostDisplacements displacements_{};
  std::span<const shared::TileBounds> tiles_;
  std::vector<sim::BodyState> bodies_;
};

}  // namespace pond::render
