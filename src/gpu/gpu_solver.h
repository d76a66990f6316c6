#pragma once
// The GPU water solver: the same model and the same step sequence as sim::CpuSolver (perturbations
// of step s applied just before its substeps), run as compute dispatches over SSBOs.
//
//  - The state lives on the GPU in two ping-pong buffers (structure of arrays, water_gpu.h);
//    a substep reads one and writes the other, so k substeps are k dispatches with a barrier
//    between each, all in one command buffer. Nothing is read back unless asked.
//  - Exact math (model.math == exact) gives the CPU solver's bits; fast math (hardware
//    inversesqrt, contraction allowed) is the same pipeline with a specialization constant.
//  - Normals are computed on the GPU into normals_buffer(), the buffer the water vertex shader
//    reads (one vec4 per node).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gpu/body_contact.h"
#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/context.h"
#include "sim/model.h"
#include "sim/normals.h"
#include "sim/session.h"
#include "sim/solver.h"
#include "sim/state.h"

namespace pond::gpu {

class GpuSolver final : public sim::Solver {
 public:
  // Starts from rest. The context must outlive the solver. The step shader stores 64 bits at a time where the context enabled shaderInt64 (faster on
  // llvmpipe, the same bits), else vec4s.
  GpuSolver(const Context& ctx, sim::WaterModel model);

  const sim::WaterModel& model() const override { return model_; }
  std::int64_t steps_done() const override { return step_; }
  std::string engine() const override { return "gpu"; }
  std::string identity() const override;  // exact math: gpu/float_policy.h's identity_line
  void set_body_models(std::vector<sim::BodyModel> bodies) override;
  std::vector<sim::BodyState> read_bodies() const override {
    return contact_ ? contact_->read() : std::vector<sim::BodyState>{};
  }

  // Advances `steps` steps (recorded in command buffers of at most kMaxDispatchesPerSubmit
  // dispatches, each submitted and waited for).
  void advance(std::int64_t steps) override;
  // Replaces the state and the step counter (the bisect mode of the parity suite uses it).
  void set_state(const sim::WaterState& state, std::int64_t steps_done) override;
  // Copies the current state back (waits for the GPU).
  sim::WaterState read_state() const override;

  // Computes the normals of the current state into normals_buffer().
  void compute_normals();
  // A frame's compute in one submission (the renderer's WaterSource): advances `steps` steps,
  // computes the normals of the new state into normals_buffer() (ready for the vertex shader and
  // transfers), makes the displacements (ux | uy | uz: the first 3 * stride floats of
  // state_buffer()) visible to the host and waits: copied into `displacements` (host-visible),
  // or, when it is null, in place (host_state(), which must then be non-null).
  // Beyond kMaxDispatchesPerSubmit dispatches the earlier steps go first, as advance() does.
  void advance_for_frame(std::int64_t steps, const Buffer* displacements);
  // The current state in host memory (ux at [0], uy at [stride], uz at [2 * stride], ...; node
  // (i, j) at i * pitch() + j of each array, water_gpu.h) where
  // the state buffers' memory is host-visible, cached and coherent (CPU devices such as
  // lavapipe): valid to read after advance_for_frame(steps, nullptr) until the next command.
  // Null elsewhere (discrete GPUs: copy instead).
  const float* host_state() const { return static_cast<const float*>(state_[cur_].mapped); }
  std::size_t stride() const { return stride_; }
  // Nodes between two rows of the state buffers: cols rounded up to 4 (gpu/water_layout.h).
  std::size_t pitch() const { return pitch_; }
  // compute_normals() and read them back, as sim::Normals.
  sim::Normals read_normals();
  // normals_buffer() read back as it is (what the last compute_normals() or advance_for_frame()
  // left; waits for the GPU).
  sim::Normals normals() const;
  const Buffer& normals_buffer() const { return normals_; }
  const Buffer& state_buffer() const { return state_[cur_]; }

  static constexpr std::int64_t kMaxDispatchesPerSubmit = 4096;

 private:
  // The constructor's steps, in order.
  void create_pipelines();
  void create_buffers();
  void map_state_where_host_readable();
  void upload_kinds_and_perturbations();
  void create_descriptor_sets();

  // Steps one submission records: kMaxDispatchesPerSubmit dispatches, counting the contact's.
  std::int64_t steps_per_submit() const;
  // Before recording `steps` steps from step_ in one submission: the kinematic bodies' schedule.
  void begin_batch(std::int64_t steps);
  void record_step(const vk::raii::CommandBuffer& cmd);
  void record_normals(const vk::raii::CommandBuffer& cmd) const;
  void record_barrier(const vk::raii::CommandBuffer& cmd) const;
  Buffer copy_to_host(const Buffer& src, const char* name) const;

  const Context& ctx_;
  sim::WaterModel model_;
  std::size_t pitch_ = 0;   // row_pitch(cols)
  std::size_t stride_ = 0;  // state_stride(rows * pitch_)
  ComputePipeline step_pipe_, perturb_pipe_, normals_pipe_;
  Buffer state_[2], kinds_, table_, normals_;
  Buffer reach_;  // the step shader's reach for the bodies' contact (POND_STEP_BINDING_REACH)
  // Texel-buffer views the step shader reads and writes the state through (water_gpu.h,
  // POND_STEP_BINDING_*): state c as R32F and RGBA32F, kinds as RGBA8UI.
  vk::raii::BufferView state_r32_[2] = {nullptr, nullptr}, state_rgba32_[2] = {nullptr, nullptr};
  vk::raii::BufferView kinds_rgba8_ = nullptr;
  std::uint32_t step_threads_x_ = 0;  // invocations per row strip of the step shader
  std::uint32_t step_local_x_ = 0;    // its workgroup width (specialization constant)
  std::uint32_t normals_local_x_ = 0; // the normals shader's (one invocation per column)
  std::vector<std::uint32_t> table_first_;  // first entry of each perturbation in table_
  vk::raii::DescriptorPool pool_ = nullptr;
  Submitter submitter_;  // advance(), compute_normals(), advance_for_frame(): no allocation per call
  // step_sets_[c]: reads state c, writes 1 - c; perturb_sets_[c], normals_sets_[c] use state c.
  std::vector<vk::raii::DescriptorSet> step_sets_, perturb_sets_, normals_sets_;
  std::unique_ptr<BodyContact> contact_;  // with bodies only: after each substep
  std::int64_t batch_first_step_ = 0;     // the first step of the submission being recorded
  int cur_ = 0;
  std::size_t next_perturbation_ = 0;
  std::int64_t step_ = 0;
};

// GpuSolvers on `ctx` for a session (sim/session.h); the context must outlive the session.
sim::GpuSolverFactory gpu_solver_factory(const Context& ctx);

}  // namespace pond::gpu
