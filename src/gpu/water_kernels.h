#pragma once
// The GPU solver's compute kernels over its two ping-pong state buffers (structure of arrays,
// shared/water_gpu.h): the step (one substep: reads state c, writes 1 - c), the perturbation (a
// table of weights added to or written into vy or y) and the normals (of state c, into the buffer
// the renderer draws with). Pipelines, texel views and descriptor sets are made once; the
// record_*() functions only record.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/context.h"
#include "gpu/water_layout.h"
#include "sim/model.h"

namespace pond::gpu {

// The buffers the kernels work on (the GPU solver's), which must outlive them.
struct WaterBuffers {
  const Buffer (&state)[2];
  const Buffer& kinds;    // node kinds, four per word (RGBA8UI texels)
  const Buffer& table;    // the model's scheduled perturbations (PerturbEntry[])
  const Buffer& normals;  // one vec4 per node, compact
  const Buffer& reach;    // the step shader's reach, for the bodies' contact
};

class WaterKernels {
 public:
  // `splash_tables`: how many more perturbation tables (the solver's splashes, one per submission
  // in flight) get sets of their own (bind_splash_table()).
  WaterKernels(const Context& ctx, const sim::WaterModel& model, std::size_t pitch, std::size_t stride,
               const WaterBuffers& buffers, std::uint32_t splash_tables);

  // One substep of the model from state c into 1 - c (a barrier must follow).
  void record_substep(const vk::raii::CommandBuffer& cmd, int c) const;
  // Entries [push.first, push.first + push.count) of the model's table (splash < 0) or of splash
  // table `splash`, applied to state c (a barrier must follow).
  void record_perturb(const vk::raii::CommandBuffer& cmd, int c, int splash, const PerturbPush& push) const;
  // Points splash table `index`'s sets at `table` (no submission may be using them).
  void bind_splash_table(std::uint32_t index, const Buffer& table);
  // The normals of state c; a barrier before it (after every earlier compute or transfer write)
  // and after it (ready for the vertex shader, the caustics' compute reads and transfers).
  void record_normals(const vk::raii::CommandBuffer& cmd, int c) const {
    record_normals_with(cmd, normals_pipe_, normals_sets_[c]);
  }
  // The same with a variant of the normals shader and its set (its first bindings the plain
  // one's, for state c): the tile bounds' (gpu/tile_kernels.h).
  void record_normals_with(const vk::raii::CommandBuffer& cmd, const ComputePipeline& pipe,
                           const vk::raii::DescriptorSet& set) const;
  std::uint32_t normals_local_x() const { return normals_local_x_; }  // its workgroup width
  // Compute and transfer writes before it made visible to compute and transfer after it (also
  // across submissions on the queue).
  static void record_barrier(const vk::raii::CommandBuffer& cmd);

  // The state's R32F views and the kinds' RGBA8UI view (the bodies' contact reads them too).
  const vk::raii::BufferView (&state_r32() const)[2] { return state_r32_; }
  const vk::raii::BufferView& kinds_rgba8() const { return kinds_rgba8_; }

 private:
  void create_pipelines(const sim::WaterModel& model);
  void create_descriptor_sets(const WaterBuffers& buffers, std::uint32_t splash_tables);

  const Context& ctx_;
  const sim::WaterModel& model_;
  std::pair<float, float> rest_;  // the step's rest lengths, edge and diagonal (sim::gpu_rest_lengths)
  std::size_t pitch_, stride_;
  ComputePipeline step_pipe_, perturb_pipe_, normals_pipe_;
  // Texel-buffer views the shaders read and write the state through (water_gpu.h,
  // POND_STEP_BINDING_*): state c as R32F and RGBA32F, kinds as RGBA8UI.
  vk::raii::BufferView state_r32_[2] = {nullptr, nullptr}, state_rgba32_[2] = {nullptr, nullptr};
  vk::raii::BufferView kinds_rgba8_ = nullptr;
  std::uint32_t step_threads_x_ = 0;  // invocations per row strip of the step shader
  std::uint32_t step_local_x_ = 0;    // its workgroup width (specialization constant)
  std::uint32_t normals_local_x_ = 0; // the normals shader's (one invocation per column)
  vk::raii::DescriptorPool pool_ = nullptr;
  // step_sets_[c]: reads state c, writes 1 - c; perturb_sets_[c], normals_sets_[c] use state c;
  // splash_sets_[2 * t + c]: splash table t on state c.
  std::vector<vk::raii::DescriptorSet> step_sets_, perturb_sets_, normals_sets_, splash_sets_;
  const Buffer* state_[2];
};

}  // namespace pond::gpu
