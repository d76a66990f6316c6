#include "gpu/water_kernels.h"

#include <algorithm>
#include <iterator>
#include <string>

#include "gpu/shaders.h"

namespace pond::gpu {
namespace {

using DT = vk::DescriptorType;

// The descriptor types of each pipeline's bindings 0..n-1 (water_gpu.h): the layouts, and the
// descriptor pool counted from them.
std::vector<DT> step_bindings() {
  std::vector<DT> b(POND_STEP_BINDINGS);
  b[POND_STEP_BINDING_SRC1] = b[POND_STEP_BINDING_SRC4] = DT::eUniformTexelBuffer;
  b[POND_STEP_BINDING_DST4] = DT::eStorageBuffer;
  b[POND_STEP_BINDING_KINDS4] = DT::eUniformTexelBuffer;
  b[POND_STEP_BINDING_REACH] = DT::eStorageBuffer;
  return b;
}
std::vector<DT> perturb_bindings() { return {DT::eStorageBuffer, DT::eStorageBuffer}; }  // state, table
std::vector<DT> normals_bindings() {
  std::vector<DT> b(POND_NORMALS_BINDINGS);
  b[POND_NORMALS_BINDING_STATE] = DT::eUniformTexelBuffer;
  b[POND_NORMALS_BINDING_NORMALS] = DT::eStorageBuffer;
  return b;
}

void write_storage(const Context& ctx, const vk::raii::DescriptorSet& set, std::initializer_list<const Buffer*> buffers) {
  std::vector<vk::DescriptorBufferInfo> infos;
  for (const Buffer* b : buffers) infos.push_back(b->whole());
  std::vector<vk::WriteDescriptorSet> writes;
  for (std::uint32_t k = 0; k < infos.size(); ++k)
    writes.push_back({.dstSet = *set, .dstBinding = k, .descriptorCount = 1, .descriptorType = DT::eStorageBuffer,
                      .pBufferInfo = &infos[k]});
  ctx.device().updateDescriptorSets(writes, nullptr);
}

}  // namespace

WaterKernels::WaterKernels(const Context& ctx, const sim::WaterModel& model, std::size_t pitch, std::size_t stride,
                           const WaterBuffers& buffers, std::uint32_t splash_tables)
    : ctx_(ctx), model_(model), rest_(sim::gpu_rest_lengths(model)), pitch_(pitch), stride_(stride),
      state_{&buffers.state[0], &buffers.state[1]} {
  create_pipelines(model);
  for (int c = 0; c < 2; ++c) {
    state_r32_[c] = create_texel_view(ctx_, buffers.state[c], vk::Format::eR32Sfloat, "the GPU solver's state");
    state_rgba32_[c] =
        create_texel_view(ctx_, buffers.state[c], vk::Format::eR32G32B32A32Sfloat, "the GPU solver's state");
  }
  kinds_rgba8_ = create_texel_view(ctx_, buffers.kinds, vk::Format::eR8G8B8A8Uint, "the GPU solver's node kinds");
  create_descriptor_sets(buffers, splash_tables);
}

void WaterKernels::create_pipelines(const sim::WaterModel& model) {
  const bool fast = model.math == sim::MathMode::fast;
  // One invocation per 4 columns (the row pitch keeps every group of 4 columns 16-byte aligned).
  // The workgroup spans the row strip in as few groups as possible (at most POND_STEP_LOCAL_X_MAX
  // invocations, a multiple of 8 = llvmpipe's lanes) and as evenly as possible: the shader's
  // barrier per row then makes a group read and write whole rows, contiguous runs the hardware
  // prefetcher follows.
  step_threads_x_ = static_cast<std::uint32_t>(pitch_ / 4);
  const std::uint32_t groups_x = std::max(1u, group_count(step_threads_x_, POND_STEP_LOCAL_X_MAX));
  step_local_x_ = std::max(8u, (group_count(step_threads_x_, groups_x) + 7u) / 8u * 8u);
  const SpecConstant step_constants[] = {
      {POND_SPEC_FAST_MATH, fast ? 1u : 0u},
      {POND_SPEC_RSQRT_STEPS, static_cast<std::uint32_t>(model.constants.rsqrt_steps)},
      {POND_SPEC_STEP_LOCAL_X, step_local_x_},
      {POND_SPEC_PADDED_ROWS, pitch_ != static_cast<std::size_t>(model.cols) ? 1u : 0u},
      {POND_SPEC_TRACK_REACH, model.bodies.empty() ? 0u : 1u}};
  const bool int64_stores = ctx_.has_int64();
  // Exact math declares DenormPreserve where the device allows it; fast math leaves denormals to
  // the device.
  const bool denorm = !fast && ctx_.denorm_preserve();
  step_pipe_ = create_compute_pipeline(ctx_, water_step_spirv(int64_stores, denorm), step_bindings(), sizeof(StepPush),
                                       step_constants,
                                       std::string(fast ? "water_step (fast" : "water_step (exact") +
                                           (int64_stores ? ", 64-bit stores" : "") + (denorm ? ", denormals kept)" : ")"));
  perturb_pipe_ = create_compute_pipeline(ctx_, water_perturb_spirv(denorm), perturb_bindings(), sizeof(PerturbPush), {},
                                          "water_perturb");
  // The normals: one invocation per column (walking a strip of rows), the row spanned by as few
  // and as evenly filled workgroups as possible, as the step shader.
  const auto cols = static_cast<std::uint32_t>(model.cols);
  const std::uint32_t normals_groups_x = std::max(1u, group_count(cols, POND_NORMALS_LOCAL_X_MAX));
  normals_local_x_ = std::max(8u, (group_count(cols, normals_groups_x) + 7u) / 8u * 8u);
  const SpecConstant normals_constants[] = {{POND_SPEC_NORMALS_LOCAL_X, normals_local_x_}};
  normals_pipe_ = create_compute_pipeline(ctx_, water_normals_spirv(denorm), normals_bindings(), sizeof(NormalsPush),
                                          normals_constants, "water_normals");
}

// Two sets of each pipeline's layout (one per ping-pong direction) and two per splash table, the
// pool sized from the layouts.
void WaterKernels::create_descriptor_sets(const WaterBuffers& buffers, std::uint32_t splash_tables) {
  const std::uint32_t perturb_sets = 2 + 2 * splash_tables;
  const std::pair<std::vector<DT>, std::uint32_t> layouts[] = {
      {step_bindings(), 2}, {perturb_bindings(), perturb_sets}, {normals_bindings(), 2}};
  std::vector<vk::DescriptorPoolSize> sizes;
  std::uint32_t max_sets = 0;
  for (const auto& [bindings, sets] : layouts) {
    max_sets += sets;
    for (const DT type : bindings) {
      auto it = std::find_if(sizes.begin(), sizes.end(), [&](const vk::DescriptorPoolSize& p) { return p.type == type; });
      if (it == sizes.end()) it = sizes.insert(sizes.end(), {.type = type, .descriptorCount = 0});
      it->descriptorCount += sets;
    }
  }
  pool_ = vk::raii::DescriptorPool(
      ctx_.device(), vk::DescriptorPoolCreateInfo{.flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                  .maxSets = max_sets,
                                                  .poolSizeCount = static_cast<std::uint32_t>(sizes.size()),
                                                  .pPoolSizes = sizes.data()});
  auto allocate = [&](const ComputePipeline& p, std::uint32_t count) {
    const std::vector<vk::DescriptorSetLayout> set_layouts(count, *p.set_layout);
    vk::raii::DescriptorSets sets(ctx_.device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *pool_,
                                                                               .descriptorSetCount = count,
                                                                               .pSetLayouts = set_layouts.data()});
    return std::vector<vk::raii::DescriptorSet>(std::make_move_iterator(sets.begin()), std::make_move_iterator(sets.end()));
  };
  step_sets_ = allocate(step_pipe_, 2);
  perturb_sets_ = allocate(perturb_pipe_, 2);
  if (splash_tables > 0) splash_sets_ = allocate(perturb_pipe_, 2 * splash_tables);
  normals_sets_ = allocate(normals_pipe_, 2);
  const std::vector<DT> step_types = step_bindings();
  for (int c = 0; c < 2; ++c) {
    std::vector<vk::BufferView> views(POND_STEP_BINDINGS);
    views[POND_STEP_BINDING_SRC1] = *state_r32_[c];
    views[POND_STEP_BINDING_SRC4] = *state_rgba32_[c];
    views[POND_STEP_BINDING_DST4] = *state_rgba32_[1 - c];
    views[POND_STEP_BINDING_KINDS4] = *kinds_rgba8_;
    std::vector<vk::WriteDescriptorSet> writes;
    const vk::DescriptorBufferInfo dst_info = buffers.state[1 - c].whole(), reach_info = buffers.reach.whole();
    for (std::uint32_t b = 0; b < views.size(); ++b)
      if (step_types[b] == DT::eStorageBuffer)
        writes.push_back({.dstSet = *step_sets_[c], .dstBinding = b, .descriptorCount = 1,
                          .descriptorType = step_types[b],
                          .pBufferInfo = b == POND_STEP_BINDING_REACH ? &reach_info : &dst_info});
      else
        writes.push_back({.dstSet = *step_sets_[c], .dstBinding = b, .descriptorCount = 1,
                          .descriptorType = step_types[b], .pTexelBufferView = &views[b]});
    ctx_.device().updateDescriptorSets(writes, nullptr);
    write_storage(ctx_, perturb_sets_[c], {&buffers.state[c], &buffers.table});
    const vk::DescriptorBufferInfo normals_info = buffers.normals.whole();
    const vk::BufferView normals_state_view = *state_r32_[c];
    const vk::WriteDescriptorSet normals_writes[] = {
        {.dstSet = *normals_sets_[c], .dstBinding = POND_NORMALS_BINDING_STATE, .descriptorCount = 1,
         .descriptorType = DT::eUniformTexelBuffer, .pTexelBufferView = &normals_state_view},
        {.dstSet = *normals_sets_[c], .dstBinding = POND_NORMALS_BINDING_NORMALS, .descriptorCount = 1,
         .descriptorType = DT::eStorageBuffer, .pBufferInfo = &normals_info}};
    ctx_.device().updateDescriptorSets(normals_writes, nullptr);
  }
}

void WaterKernels::bind_splash_table(std::uint32_t index, const Buffer& table) {
  for (int c = 0; c < 2; ++c) write_storage(ctx_, splash_sets_[2 * index + static_cast<std::uint32_t>(c)], {state_[c], &table});
}

void WaterKernels::record_barrier(const vk::raii::CommandBuffer& cmd) {
  using S = vk::PipelineStageFlagBits2;
  using A = vk::AccessFlagBits2;
  const vk::MemoryBarrier2 barrier{.srcStageMask = S::eComputeShader | S::eTransfer,
                                   .srcAccessMask = A::eShaderWrite | A::eTransferWrite,
                                   .dstStageMask = S::eComputeShader | S::eTransfer,
                                   .dstAccessMask = A::eShaderRead | A::eShaderWrite | A::eTransferRead};
  cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &barrier});
}

void WaterKernels::record_substep(const vk::raii::CommandBuffer& cmd, int c) const {
  const sim::StepConstants& k = model_.constants;
  const auto rows = static_cast<std::uint32_t>(model_.rows);
  const StepPush push{.rows = rows, .cols = static_cast<std::uint32_t>(model_.cols),
                      .stride = static_cast<std::uint32_t>(stride_), .pitch = static_cast<std::uint32_t>(pitch_),
                      .kc = k.kc, .kd = k.kd, .dt = k.dt, .rest_edge = rest_.first, .rest_diag = rest_.second};
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *step_pipe_.pipeline);
  cmd.pushConstants<StepPush>(*step_pipe_.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *step_pipe_.layout, 0, *step_sets_[c], nullptr);
  cmd.dispatch(group_count(step_threads_x_, step_local_x_), group_count(rows, POND_STEP_ROWS_PER_INVOCATION), 1);
}

void WaterKernels::record_perturb(const vk::raii::CommandBuffer& cmd, int c, int splash, const PerturbPush& push) const {
  const vk::raii::DescriptorSet& set = splash < 0 ? perturb_sets_[c] : splash_sets_[2 * splash + c];
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *perturb_pipe_.pipeline);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *perturb_pipe_.layout, 0, *set, nullptr);
  cmd.pushConstants<PerturbPush>(*perturb_pipe_.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
  cmd.dispatch(group_count(push.count, POND_PERTURB_LOCAL_X), 1, 1);
}

void WaterKernels::record_normals_with(const vk::raii::CommandBuffer& cmd, const ComputePipeline& pipe,
                                       const vk::raii::DescriptorSet& set) const {
  const NormalsPush push{.rows = static_cast<std::uint32_t>(model_.rows),
                         .cols = static_cast<std::uint32_t>(model_.cols),
                         .stride = static_cast<std::uint32_t>(stride_),
                         .pitch = static_cast<std::uint32_t>(pitch_)};
  record_barrier(cmd);
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipe.pipeline);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipe.layout, 0, *set, nullptr);
  cmd.pushConstants<NormalsPush>(*pipe.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
  cmd.dispatch(group_count(push.cols, normals_local_x_), group_count(push.rows, POND_NORMALS_ROWS_PER_INVOCATION), 1);
  using S = vk::PipelineStageFlagBits2;
  using A = vk::AccessFlagBits2;
  const vk::MemoryBarrier2 after{
      .srcStageMask = S::eComputeShader, .srcAccessMask = A::eShaderWrite,
      .dstStageMask = S::eVertexShader | S::eVertexAttributeInput | S::eComputeShader | S::eTransfer,
      .dstAccessMask = A::eShaderRead | A::eVertexAttributeRead | A::eTransferRead};
  cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &after});
}

}  // namespace pond::gpu
