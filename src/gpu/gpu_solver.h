#pragma once
// The GPU water solver: the same model and the same step sequence as sim::CpuSolver (perturbations
// of step s applied just before its substeps), run as compute dispatches over SSBOs.
//
//  - The state lives on the GPU in two ping-pong buffers (structure of arrays, water_gpu.h);
//    a substep reads one and writes the other, so k substeps are k dispatches with a barrier
//    between each, all in one command buffer (gpu/water_kernels.h).
//  - Work is submitted without waiting (gpu/submission_ring.h). A drawn solver's every submission
//    ends by publishing the state: the normals (normals_buffer(), what the water's vertex shader
//    reads) and small host-readable copies (the displacements where the state's memory is not
//    host-readable, and the bodies); displacements() and read_bodies() wait for the last one. An
//    undrawn solver (pond simulate, benchmarks) publishes only when they ask. A splash is a dispatch in the next submission, never a round trip: those two show it
//    once that submission is made (the next advance(), or read_state(), which submits it first).
//  - Every so often a submission also copies the state to the host (gpu/state_snapshots.h): the
//    copy a CPU solver goes on from when the device is lost (host_snapshot()). Vulkan's failures
//    leave every entry point as GpuFailure (gpu/gpu_failure.h).
//  - Exact math (model.math == exact) gives the CPU solver's bits; fast math (hardware
//    inversesqrt, contraction allowed) is the same pipeline with a specialization constant.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "gpu/body_contact.h"
#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/displacement_readback.h"
#include "gpu/state_snapshots.h"
#include "gpu/submission_ring.h"
#include "gpu/tile_kernels.h"
#include "gpu/water_kernels.h"
#include "gpu/water_layout.h"
#include "sim/model.h"
#include "sim/normals.h"
#include "sim/solver.h"
#include "sim/state.h"

namespace pond::gpu {

class GpuSolver : public sim::Solver {
 public:
  // Starts from rest. The context must outlive the solver. The step shader stores 64 bits at a
  // time where the context enabled shaderInt64 (faster on llvmpipe, the same bits), else vec4s.
  // `drawn`: every submission publishes the state (see the top), for a renderer's frames.
  GpuSolver(const Context& ctx, sim::WaterModel model, bool drawn = false);
  // Waits for the queue: frames in flight may still read the solver's buffers.
  ~GpuSolver() override;

  const sim::WaterModel& model() const override { return model_; }
  std::int64_t steps_done() const override { return step_; }
  std::string engine() const override { return "gpu"; }
  std::string identity() const override;  // exact math: gpu/float_policy.h's identity_line
  void set_body_models(std::vector<sim::BodyModel> bodies) override;

  // Submits `steps` steps (with the splashes since the last submission first) in command buffers
  // of at most kMaxDispatchesPerSubmit dispatches, without waiting. steps 0 submits the splashes.
  void advance(std::int64_t steps) override;
  void perturb(const sim::PerturbationTable& table) override;
  // Replaces the state and the step counter (uploads it, waiting; then submits its normals and
  // copies). Splashes not yet submitted are dropped, as the state they applied to.
  void set_state(const sim::WaterState& state, std::int64_t steps_done) override;
  sim::WaterState read_state() override;  // copies the state back (waits)
  sim::HostDisplacements displacements() override;
  // Where the state is not host-readable in place, submissions copy only the windows kept
  // (gpu/displacement_readback.h); in place (lavapipe) every node is held anyway.
  void keep_on_host(std::optional<std::vector<core::GridWindow>> windows) override;
  bool holds_on_host(const core::GridWindow& w) override;
  void bring_to_host(std::span<const core::GridWindow> windows) override;
  std::vector<sim::BodyState> read_bodies() override;
  const sim::HostSnapshot* host_snapshot() override;

  // Substeps between the host's copies of the state (StateSnapshots; 0: none, for benchmarks).
  void set_host_copy_interval(std::int64_t substeps) { snapshots_->set_interval(substeps); }
  // Waits until every submission finished (benchmarks time the steps, not their submission).
  void finish() { ring_->finish_all(); }
  std::size_t stride() const { return stride_; }  // floats between the state's component arrays
  // Nodes between two rows of the state buffers: cols rounded up to 4 (gpu/water_layout.h).
  std::size_t pitch() const { return pitch_; }
  // The normals of the current state, read back (waits).
  sim::Normals normals();
  // What the renderer draws from, as the last submission left it: the state now (its first
  // 3 * stride floats are ux | uy | uz), the normals, the bodies (null without bodies).
  const Buffer& state_buffer() const { return state_[cur_]; }
  const Buffer& normals_buffer() const { return normals_; }
  const Buffer* bodies_buffer() const { return contact_ ? &contact_->bodies() : nullptr; }

  // Whether every submission that publishes (as above; readers that wait make one) also leaves
  // the tile bounds (shared/tile_bounds.h) of its state, with sim::compute_tile_bounds's bits.
  // Off by default: the plain normals pass, no buffers. Switching on submits the current state's
  // bounds; switching off waits for the queue (frames in flight may read them).
  void track_tile_bounds(bool on) override;
  // The current state's tile bounds on the host, tile (a, b) at b * tiles_x + a, valid as
  // displacements() is (it waits for the last submission, as that does); empty while not tracked.
  std::span<const sim::TileBounds> tile_bounds() override;
  // The same in the GPU's buffer as the last submission left it (a renderer copies or binds it;
  // as normals_buffer(): storage, transfer source), and their grid; null while not tracked.
  const Buffer* tile_bounds_buffer() const { return tiles_ ? &tiles_->bounds() : nullptr; }
  const sim::TileGrid& tile_grid() const { return tile_grid_; }

  static constexpr std::int64_t kMaxDispatchesPerSubmit = 4096;

 private:
  void create_buffers();
  void upload_state(const sim::WaterState& state, std::int64_t steps_done);  // set_state's work
  sim::WaterState read_state_now();                                           // read_state's
  void track_tiles(bool on);                                                  // track_tile_bounds's
  void map_state_where_host_readable();
  void upload_kinds_and_perturbations();

  // Steps one submission records: kMaxDispatchesPerSubmit dispatches, counting the contact's.
  std::int64_t steps_per_submit() const;
  // One submission: the queued splashes, `steps` steps, and with `publish` the normals and the
  // host copies.
  void submit(std::int64_t steps, bool publish);
  // The last submission, finished and published (one that publishes submitted first if it was not).
  Submission& published();
  void record_splashes(const vk::raii::CommandBuffer& cmd, Submission& s);
  void record_step(const vk::raii::CommandBuffer& cmd, std::uint32_t region, std::int64_t first_step);
  void record_copies(const vk::raii::CommandBuffer& cmd, const Submission& s);
  // The splashes queued since the last submission, submitted (read_*() see them).
  void flush_splashes();
  Buffer copy_to_host(const Buffer& src, const char* name);

  const Context& ctx_;
  sim::WaterModel model_;
  bool drawn_ = false;
  std::size_t pitch_ = 0;   // row_pitch(cols)
  std::size_t stride_ = 0;  // state_stride(rows * pitch_)
  Buffer state_[2], kinds_, table_, normals_;
  Buffer reach_;  // the step shader's reach for the bodies' contact (POND_STEP_BINDING_REACH)
  std::vector<std::uint32_t> table_first_;  // first entry of each perturbation in table_
  std::unique_ptr<WaterKernels> kernels_;
  std::unique_ptr<BodyContact> contact_;  // with bodies only: after each substep
  sim::TileGrid tile_grid_;
  std::unique_ptr<TileKernels> tiles_;    // while the tile bounds are tracked: with the normals
  std::unique_ptr<SubmissionRing> ring_;
  std::unique_ptr<DisplacementReadback> readback_;  // where the state is not read in place
  std::unique_ptr<StateSnapshots> snapshots_;
  std::vector<PerturbEntry> splash_entries_;  // queued, node = row * pitch + col
  std::vector<PerturbPush> splash_pushes_;    // one per queued splash (first: into entries)
  int cur_ = 0;
  std::size_t next_perturbation_ = 0;
  std::int64_t step_ = 0;
};

}  // namespace pond::gpu
