#include "gpu/gpu_solver.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/errors.h"
#include "gpu/float_policy.h"
#include "gpu/shaders.h"
#include "gpu/water_layout.h"

namespace pond::gpu {
namespace {

using BU = vk::BufferUsageFlagBits;

// The model's kinds (node row * cols + col) with the GPU state's row pitch, packed four per word
// (water_gpu.h); the padding columns are fixed nodes, which keeps their state at +0 (water_step.comp).
std::vector<std::uint32_t> pack_kinds(const sim::WaterModel& model, std::size_t pitch) {
  const auto rows = static_cast<std::size_t>(model.rows), cols = static_cast<std::size_t>(model.cols);
  std::vector<std::uint32_t> words((rows * pitch + 3) / 4 + 1, 0u);  // +1: never empty
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < pitch; ++j) {
      const std::size_t n = i * pitch + j;
      const std::uint32_t kind = j < cols ? std::uint32_t{model.kinds[i * cols + j]} : shared::kNodeFixed;
      words[n / 4] |= kind << (8 * (n % 4));
    }
  return words;
}

// The six component arrays of a state, each `stride` floats, rows `pitch` nodes apart (padding +0).
std::vector<float> to_soa_words(const sim::WaterState& s, std::size_t rows, std::size_t cols, std::size_t pitch,
                                std::size_t stride) {
  std::vector<float> words(stride * kComponents, 0.0f);
  const float* const src[kComponents] = {s.ux.data(), s.uy.data(), s.uz.data(), s.vx.data(), s.vy.data(), s.vz.data()};
  for (unsigned c = 0; c < kComponents; ++c)
    for (std::size_t i = 0; i < rows; ++i)
      std::memcpy(&words[c * stride + i * pitch], src[c] + i * cols, cols * sizeof(float));
  return words;
}

void write_set(const Context& ctx, const vk::raii::DescriptorSet& set, std::initializer_list<const Buffer*> buffers) {
  std::vector<vk::DescriptorBufferInfo> infos;
  for (const Buffer* b : buffers) infos.push_back(b->whole());
  std::vector<vk::WriteDescriptorSet> writes;
  for (std::uint32_t k = 0; k < infos.size(); ++k)
    writes.push_back({.dstSet = *set, .dstBinding = k, .descriptorCount = 1,
                      .descriptorType = vk::DescriptorType::eStorageBuffer, .pBufferInfo = &infos[k]});
  ctx.device().updateDescriptorSets(writes, nullptr);
}

// The descriptor types of each pipeline's bindings 0..n-1 (water_gpu.h): the layouts, and the
// descriptor pool counted from them.
std::vector<vk::DescriptorType> step_bindings() {
  using DT = vk::DescriptorType;
  std::vector<DT> b(POND_STEP_BINDINGS);
  b[POND_STEP_BINDING_SRC1] = b[POND_STEP_BINDING_SRC4] = DT::eUniformTexelBuffer;
  b[POND_STEP_BINDING_DST4] = DT::eStorageBuffer;
  b[POND_STEP_BINDING_KINDS4] = DT::eUniformTexelBuffer;
  b[POND_STEP_BINDING_REACH] = DT::eStorageBuffer;
  return b;
}
std::vector<vk::DescriptorType> perturb_bindings() {
  return {vk::DescriptorType::eStorageBuffer, vk::DescriptorType::eStorageBuffer};  // state, table
}
std::vector<vk::DescriptorType> normals_bindings() {
  std::vector<vk::DescriptorType> b(POND_NORMALS_BINDINGS);
  b[POND_NORMALS_BINDING_STATE] = vk::DescriptorType::eUniformTexelBuffer;
  b[POND_NORMALS_BINDING_NORMALS] = vk::DescriptorType::eStorageBuffer;
  return b;
}

}  // namespace

GpuSolver::GpuSolver(const Context& ctx, sim::WaterModel model)
    : ctx_(ctx),
      model_(std::move(model)),
      pitch_(row_pitch(static_cast<std::size_t>(model_.cols))),
      stride_(state_stride(static_cast<std::size_t>(model_.rows) * pitch_)),
      submitter_(ctx, "water compute") {
  create_pipelines();
  create_buffers();
  map_state_where_host_readable();
  upload_kinds_and_perturbations();
  create_descriptor_sets();
  if (!model_.bodies.empty())
    contact_ = std::make_unique<BodyContact>(ctx_, model_, pitch_, stride_, state_, state_r32_, kinds_rgba8_, reach_,
                                             steps_per_submit() * model_.substeps, 1,
                                             model_.math == sim::MathMode::exact && ctx_.denorm_preserve());
  set_state(sim::rest_state(model_), 0);
}

void GpuSolver::create_pipelines() {
  const bool fast = model_.math == sim::MathMode::fast;
  // The row pitch keeps every group of 4 columns 16-byte aligned (the stride is a multiple of 16
  // floats), so the step shader can move 4 nodes per texel on every grid.
  // One invocation per 4 columns. The workgroup spans the row strip in as few groups as possible (at most POND_STEP_LOCAL_X_MAX invocations, a
  // multiple of 8 = llvmpipe's lanes) and as evenly as possible: the shader's barrier per row then
  // makes a group read and write whole rows, contiguous runs the hardware prefetcher follows.
  step_threads_x_ = static_cast<std::uint32_t>(pitch_ / 4);
  const std::uint32_t groups_x = std::max(1u, group_count(step_threads_x_, POND_STEP_LOCAL_X_MAX));
  step_local_x_ = std::max(8u, (group_count(step_threads_x_, groups_x) + 7u) / 8u * 8u);
  const SpecConstant step_constants[] = {
      {POND_SPEC_FAST_MATH, fast ? 1u : 0u},
      {POND_SPEC_RSQRT_STEPS, static_cast<std::uint32_t>(model_.constants.rsqrt_steps)},
      {POND_SPEC_STEP_LOCAL_X, step_local_x_},
      {POND_SPEC_PADDED_ROWS, pitch_ != static_cast<std::size_t>(model_.cols) ? 1u : 0u},
      {POND_SPEC_TRACK_REACH, model_.bodies.empty() ? 0u : 1u}};
  const bool int64_stores = ctx_.has_int64();
  // Exact math declares DenormPreserve where the device allows it; fast math leaves denormals to
  // the device.
  const bool denorm = !fast && ctx_.denorm_preserve();
  step_pipe_ = create_compute_pipeline(ctx_, water_step_spirv(int64_stores, denorm),
                                       step_bindings(), sizeof(StepPush), step_constants,
                                       std::string(fast ? "water_step (fast" : "water_step (exact") +
                                           (int64_stores ? ", 64-bit stores" : "") + (denorm ? ", denormals kept)" : ")"));
  perturb_pipe_ = create_compute_pipeline(ctx_, water_perturb_spirv(denorm), perturb_bindings(), sizeof(PerturbPush), {},
                                          "water_perturb");
  // The normals: one invocation per column (walking a strip of rows), the row spanned by as few
  // and as evenly filled workgroups as possible, as the step shader.
  const auto cols = static_cast<std::uint32_t>(model_.cols);
  const std::uint32_t normals_groups_x = std::max(1u, group_count(cols, POND_NORMALS_LOCAL_X_MAX));
  normals_local_x_ = std::max(8u, (group_count(cols, normals_groups_x) + 7u) / 8u * 8u);
  const SpecConstant normals_constants[] = {{POND_SPEC_NORMALS_LOCAL_X, normals_local_x_}};
  normals_pipe_ = create_compute_pipeline(ctx_, water_normals_spirv(denorm), normals_bindings(), sizeof(NormalsPush),
                                          normals_constants, "water_normals");
}

void GpuSolver::create_buffers() {
  const vk::DeviceSize state_bytes = stride_ * kComponents * sizeof(float);
  const auto state_usage = BU::eStorageBuffer | BU::eUniformTexelBuffer | BU::eTransferSrc | BU::eTransferDst;
  state_[0] = create_buffer(ctx_, state_bytes, state_usage, MemoryUse::device, "water state A");
  state_[1] = create_buffer(ctx_, state_bytes, state_usage, MemoryUse::device, "water state B");
  normals_ = create_buffer(ctx_, std::max<std::size_t>(1, model_.nodes()) * 4 * sizeof(float),
                           BU::eStorageBuffer | BU::eTransferSrc | BU::eVertexBuffer | BU::eUniformTexelBuffer,
                           MemoryUse::device, "water normals");  // texel buffer: render/caustics_pass.h reads it
  // The reach the step shader keeps for the bodies' contact (POND_STEP_BINDING_REACH), from 0; the
  // contact pass sets it back to 0 after every substep.
  reach_ = create_buffer(ctx_, sizeof(std::uint32_t), BU::eStorageBuffer | BU::eTransferDst, MemoryUse::device,
                         "water reach");
  const std::uint32_t zero = 0;
  upload(ctx_, reach_, std::as_bytes(std::span(&zero, 1)));
}

// Where every device-local memory type the state could be in is also host-visible, cached and
// coherent (lavapipe: the "GPU" memory is the CPU's), the state stays mapped and the renderer
// reads the displacements in place instead of copying them each frame (host_state()).
void GpuSolver::map_state_where_host_readable() {
  using MP = vk::MemoryPropertyFlagBits;
  const vk::MemoryPropertyFlags host = MP::eHostVisible | MP::eHostCached | MP::eHostCoherent;
  const vk::PhysicalDeviceMemoryProperties props = ctx_.physical().getMemoryProperties();
  const std::uint32_t bits = state_[0].buffer.getMemoryRequirements().memoryTypeBits;
  for (std::uint32_t t = 0; t < props.memoryTypeCount; ++t) {
    const vk::MemoryPropertyFlags flags = props.memoryTypes[t].propertyFlags;
    if ((bits >> t & 1u) && (flags & MP::eDeviceLocal) && (flags & host) != host) return;
  }
  for (Buffer& b : state_) b.mapped = b.memory.mapMemory(0, VK_WHOLE_SIZE);
}

void GpuSolver::upload_kinds_and_perturbations() {
  const std::vector<std::uint32_t> kinds = pack_kinds(model_, pitch_);
  kinds_ = create_buffer(ctx_, kinds.size() * 4, BU::eUniformTexelBuffer | BU::eStorageBuffer | BU::eTransferDst,
                         MemoryUse::device,
                         "water node kinds");
  upload(ctx_, kinds_, std::as_bytes(std::span(kinds)));

  // The model's tables name node row * cols + col; the state's node is row * pitch + col.
  std::vector<PerturbEntry> table;
  const auto model_cols = static_cast<std::size_t>(model_.cols);
  for (const sim::PerturbationTable& t : model_.perturbations) {
    table_first_.push_back(static_cast<std::uint32_t>(table.size()));
    for (std::size_t k = 0; k < t.nodes.size(); ++k) {
      const std::size_t i = t.nodes[k] / model_cols, j = t.nodes[k] % model_cols;
      table.push_back({static_cast<std::uint32_t>(i * pitch_ + j), t.weights[k]});
    }
  }
  table_ = create_buffer(ctx_, std::max<std::size_t>(1, table.size()) * sizeof(PerturbEntry),
                         BU::eStorageBuffer | BU::eTransferDst, MemoryUse::device, "perturbation table");
  upload(ctx_, table_, std::as_bytes(std::span(table)));
}

// Two sets of each pipeline's layout (one per ping-pong direction), the pool sized from the layouts.
void GpuSolver::create_descriptor_sets() {
  using DT = vk::DescriptorType;
  for (int c = 0; c < 2; ++c) {
    state_r32_[c] = create_texel_view(ctx_, state_[c], vk::Format::eR32Sfloat, "the GPU solver's state");
    state_rgba32_[c] = create_texel_view(ctx_, state_[c], vk::Format::eR32G32B32A32Sfloat, "the GPU solver's state");
  }
  kinds_rgba8_ = create_texel_view(ctx_, kinds_, vk::Format::eR8G8B8A8Uint, "the GPU solver's node kinds");

  constexpr std::uint32_t kSetsPerPipeline = 2;
  const std::vector<DT> layouts[] = {step_bindings(), perturb_bindings(), normals_bindings()};
  std::vector<vk::DescriptorPoolSize> sizes;
  for (const std::vector<DT>& bindings : layouts)
    for (const DT type : bindings) {
      auto it = std::find_if(sizes.begin(), sizes.end(), [&](const vk::DescriptorPoolSize& p) { return p.type == type; });
      if (it == sizes.end()) it = sizes.insert(sizes.end(), {.type = type, .descriptorCount = 0});
      it->descriptorCount += kSetsPerPipeline;
    }
  pool_ = vk::raii::DescriptorPool(
      ctx_.device(), vk::DescriptorPoolCreateInfo{.flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                  .maxSets = kSetsPerPipeline * std::size(layouts),
                                                  .poolSizeCount = static_cast<std::uint32_t>(sizes.size()),
                                                  .pPoolSizes = sizes.data()});
  auto allocate = [&](const ComputePipeline& p) {
    const vk::DescriptorSetLayout set_layouts[kSetsPerPipeline] = {*p.set_layout, *p.set_layout};
    vk::raii::DescriptorSets sets(ctx_.device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *pool_,
                                                                               .descriptorSetCount = kSetsPerPipeline,
                                                                               .pSetLayouts = set_layouts});
    return std::vector<vk::raii::DescriptorSet>(std::make_move_iterator(sets.begin()),
                                                std::make_move_iterator(sets.end()));
  };
  step_sets_ = allocate(step_pipe_);
  perturb_sets_ = allocate(perturb_pipe_);
  normals_sets_ = allocate(normals_pipe_);
  const std::vector<DT> step_types = step_bindings();
  for (int c = 0; c < 2; ++c) {
    std::vector<vk::BufferView> views(POND_STEP_BINDINGS);
    views[POND_STEP_BINDING_SRC1] = *state_r32_[c];
    views[POND_STEP_BINDING_SRC4] = *state_rgba32_[c];
    views[POND_STEP_BINDING_DST4] = *state_rgba32_[1 - c];
    views[POND_STEP_BINDING_KINDS4] = *kinds_rgba8_;
    std::vector<vk::WriteDescriptorSet> writes;
    const vk::DescriptorBufferInfo dst_info = state_[1 - c].whole(), reach_info = reach_.whole();
    for (std::uint32_t b = 0; b < views.size(); ++b)
      if (step_types[b] == DT::eStorageBuffer)
        writes.push_back({.dstSet = *step_sets_[c], .dstBinding = b, .descriptorCount = 1,
                          .descriptorType = step_types[b],
                          .pBufferInfo = b == POND_STEP_BINDING_REACH ? &reach_info : &dst_info});
      else
        writes.push_back({.dstSet = *step_sets_[c], .dstBinding = b, .descriptorCount = 1,
                          .descriptorType = step_types[b], .pTexelBufferView = &views[b]});
    ctx_.device().updateDescriptorSets(writes, nullptr);
    write_set(ctx_, perturb_sets_[c], {&state_[c], &table_});
    const vk::DescriptorBufferInfo normals_info = normals_.whole();
    const vk::BufferView normals_state_view = *state_r32_[c];
    const vk::WriteDescriptorSet normals_writes[] = {
        {.dstSet = *normals_sets_[c], .dstBinding = POND_NORMALS_BINDING_STATE, .descriptorCount = 1,
         .descriptorType = DT::eUniformTexelBuffer, .pTexelBufferView = &normals_state_view},
        {.dstSet = *normals_sets_[c], .dstBinding = POND_NORMALS_BINDING_NORMALS, .descriptorCount = 1,
         .descriptorType = DT::eStorageBuffer, .pBufferInfo = &normals_info}};
    ctx_.device().updateDescriptorSets(normals_writes, nullptr);
  }
}

void GpuSolver::set_state(const sim::WaterState& state, std::int64_t steps_done) {
  if (state.nodes() != model_.nodes()) throw InternalError("GpuSolver::set_state: the state has the wrong node count");
  const std::vector<float> words = to_soa_words(state, static_cast<std::size_t>(model_.rows),
                                                static_cast<std::size_t>(model_.cols), pitch_, stride_);
  cur_ = 0;
  // Into both buffers: the padding of either is then +0 (the step shader keeps it so).
  for (const Buffer& b : state_) upload(ctx_, b, std::as_bytes(std::span(words)));
  if (contact_) contact_->set_bodies(state.bodies);
  else if (!state.bodies.empty()) throw InternalError("GpuSolver::set_state: bodies for a model without bodies");
  step_ = steps_done;
  next_perturbation_ = 0;
  while (next_perturbation_ < model_.perturbations.size() && model_.perturbations[next_perturbation_].step < step_)
    ++next_perturbation_;
}

// Every dispatch reads what the previous one wrote (read-after-write) and overwrites what the one
// before read (write-after-read); a compute->compute memory barrier orders both. It also makes the
// uploads and copies of earlier submissions visible (second scope: later commands on the queue).
void GpuSolver::record_barrier(const vk::raii::CommandBuffer& cmd) const {
  using S = vk::PipelineStageFlagBits2;
  using A = vk::AccessFlagBits2;
  const vk::MemoryBarrier2 barrier{.srcStageMask = S::eComputeShader | S::eTransfer,
                                   .srcAccessMask = A::eShaderWrite | A::eTransferWrite,
                                   .dstStageMask = S::eComputeShader | S::eTransfer,
                                   .dstAccessMask = A::eShaderRead | A::eShaderWrite | A::eTransferRead};
  cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &barrier});
}

// One step: its perturbations, then its substeps, each dispatch behind a barrier.
void GpuSolver::record_step(const vk::raii::CommandBuffer& cmd) {
  const auto rows = static_cast<std::uint32_t>(model_.rows), cols = static_cast<std::uint32_t>(model_.cols);
  const auto stride = static_cast<std::uint32_t>(stride_);
  while (next_perturbation_ < model_.perturbations.size() &&
         model_.perturbations[next_perturbation_].step == step_) {
    const sim::PerturbationTable& t = model_.perturbations[next_perturbation_];
    const PerturbPush push{
        .first = table_first_[next_perturbation_], .count = static_cast<std::uint32_t>(t.nodes.size()),
        .stride = stride,
        .target = t.target == sim::PerturbTarget::velocity ? shared::kPerturbVelocity : shared::kPerturbPosition,
        .mode = t.mode == sim::PerturbMode::add ? shared::kPerturbAdd : shared::kPerturbSet};
    ++next_perturbation_;
    if (push.count == 0) continue;
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *perturb_pipe_.pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *perturb_pipe_.layout, 0, *perturb_sets_[cur_], nullptr);
    cmd.pushConstants<PerturbPush>(*perturb_pipe_.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
    cmd.dispatch(group_count(push.count, POND_PERTURB_LOCAL_X), 1, 1);
    record_barrier(cmd);
  }
  const sim::StepConstants& k = model_.constants;
  const StepPush push{.rows = rows, .cols = cols, .stride = stride, .pitch = static_cast<std::uint32_t>(pitch_),
                      .kc = k.kc, .kd = k.kd,
                      .dt = k.dt, .rest_edge = k.rest_edge, .rest_diag = k.rest_diag};
  for (int s = 0; s < model_.substeps; ++s) {
    if (s == 0 || contact_) {  // the contact pass binds its own pipeline
      cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *step_pipe_.pipeline);
      cmd.pushConstants<StepPush>(*step_pipe_.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
    }
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *step_pipe_.layout, 0, *step_sets_[cur_], nullptr);
    cmd.dispatch(group_count(step_threads_x_, step_local_x_), group_count(rows, POND_STEP_ROWS_PER_INVOCATION), 1);
    record_barrier(cmd);
    cur_ = 1 - cur_;
    if (contact_) {
      contact_->record(cmd, cur_, 0, (step_ - batch_first_step_) * model_.substeps + s);
      record_barrier(cmd);
    }
  }
  ++step_;
}

std::int64_t GpuSolver::steps_per_submit() const {
  const std::int64_t dispatches_per_step = std::int64_t{std::max(1, model_.substeps)} * (model_.bodies.empty() ? 1 : 2);
  return std::max<std::int64_t>(1, kMaxDispatchesPerSubmit / dispatches_per_step);
}

void GpuSolver::begin_batch(std::int64_t steps) {
  batch_first_step_ = step_;
  if (contact_) contact_->write_schedule(step_, steps, 0);
}

void GpuSolver::advance(std::int64_t steps) {
  while (steps > 0) {
    const std::int64_t n = std::min(steps, steps_per_submit());
    begin_batch(n);
    submitter_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
      record_barrier(cmd);
      for (std::int64_t s = 0; s < n; ++s) record_step(cmd);
    });
    steps -= n;
  }
}

// Copies `src` into a new host-visible buffer after every compute or transfer write before it, and
// makes the copy visible to the host.
Buffer GpuSolver::copy_to_host(const Buffer& src, const char* name) const {
  Buffer staging = create_buffer(ctx_, src.size, BU::eTransferDst, MemoryUse::readback, name);
  ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    record_barrier(cmd);
    cmd.copyBuffer(*src.buffer, *staging.buffer, vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = src.size});
    const vk::MemoryBarrier2 to_host{.srcStageMask = vk::PipelineStageFlagBits2::eTransfer,
                                     .srcAccessMask = vk::AccessFlagBits2::eTransferWrite,
                                     .dstStageMask = vk::PipelineStageFlagBits2::eHost,
                                     .dstAccessMask = vk::AccessFlagBits2::eHostRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
  });
  staging.invalidate(ctx_);
  return staging;
}

sim::WaterState GpuSolver::read_state() const {
  const Buffer staging = copy_to_host(state_[cur_], "state readback");
  sim::WaterState s(model_.nodes());
  if (contact_) s.bodies = contact_->read();
  const auto* words = static_cast<const float*>(staging.mapped);
  float* const dst[kComponents] = {s.ux.data(), s.uy.data(), s.uz.data(), s.vx.data(), s.vy.data(), s.vz.data()};
  const auto rows = static_cast<std::size_t>(model_.rows), cols = static_cast<std::size_t>(model_.cols);
  for (unsigned c = 0; c < kComponents; ++c)  // drops the padding: rows * cols, as sim::WaterState
    for (std::size_t i = 0; i < rows; ++i)
      std::memcpy(dst[c] + i * cols, words + c * stride_ + i * pitch_, cols * sizeof(float));
  return s;
}

// The normals of the current state; before it, a barrier after every earlier compute or transfer
// write; after it, the normals (and the state) made ready for the vertex shader and transfers.
void GpuSolver::record_normals(const vk::raii::CommandBuffer& cmd) const {
  const NormalsPush push{.rows = static_cast<std::uint32_t>(model_.rows),
                         .cols = static_cast<std::uint32_t>(model_.cols),
                         .stride = static_cast<std::uint32_t>(stride_),
                         .pitch = static_cast<std::uint32_t>(pitch_)};
  record_barrier(cmd);
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *normals_pipe_.pipeline);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *normals_pipe_.layout, 0, *normals_sets_[cur_], nullptr);
  cmd.pushConstants<NormalsPush>(*normals_pipe_.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
  cmd.dispatch(group_count(push.cols, normals_local_x_), group_count(push.rows, POND_NORMALS_ROWS_PER_INVOCATION), 1);
  // The vertex shader of the renderer reads them next.
  const vk::MemoryBarrier2 to_vertex{
      .srcStageMask = vk::PipelineStageFlagBits2::eComputeShader,
      .srcAccessMask = vk::AccessFlagBits2::eShaderWrite,
      .dstStageMask = vk::PipelineStageFlagBits2::eVertexShader | vk::PipelineStageFlagBits2::eVertexAttributeInput |
                      vk::PipelineStageFlagBits2::eTransfer,
      .dstAccessMask = vk::AccessFlagBits2::eShaderRead | vk::AccessFlagBits2::eVertexAttributeRead |
                       vk::AccessFlagBits2::eTransferRead};
  cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_vertex});
}

void GpuSolver::compute_normals() {
  submitter_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) { record_normals(cmd); });
}

void GpuSolver::advance_for_frame(std::int64_t steps, const Buffer* displacements) {
  const vk::DeviceSize bytes = 3 * stride_ * sizeof(float);
  if (displacements ? displacements->size < bytes : host_state() == nullptr)
    throw RuntimeError("GpuSolver::advance_for_frame: no readback buffer of " + std::to_string(bytes) +
                       " bytes, and the state is not host-readable");
  const std::int64_t per_submit = steps_per_submit();
  if (steps > per_submit) advance(steps - per_submit);
  const std::int64_t last = std::min(steps, per_submit);
  begin_batch(last);
  submitter_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    record_barrier(cmd);
    for (std::int64_t s = 0; s < last; ++s) record_step(cmd);
    record_normals(cmd);
    using S = vk::PipelineStageFlagBits2;
    using A = vk::AccessFlagBits2;
    if (displacements) {
      // record_normals() ended with a compute -> transfer barrier; the last step's barrier
      // covers the state for the copy.
      cmd.copyBuffer(*state_[cur_].buffer, *displacements->buffer,
                     vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = bytes});
      const vk::MemoryBarrier2 to_host{.srcStageMask = S::eCopy, .srcAccessMask = A::eTransferWrite,
                                       .dstStageMask = S::eHost, .dstAccessMask = A::eHostRead};
      cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
    } else {
      // The state the substeps (or set_state's upload) wrote, read by the host in place.
      const vk::MemoryBarrier2 to_host{.srcStageMask = S::eComputeShader | S::eTransfer,
                                       .srcAccessMask = A::eShaderWrite | A::eTransferWrite,
                                       .dstStageMask = S::eHost, .dstAccessMask = A::eHostRead};
      cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
    }
  });
}

sim::Normals GpuSolver::read_normals() {
  compute_normals();
  return normals();
}

sim::Normals GpuSolver::normals() const {
  const Buffer staging = copy_to_host(normals_, "normals readback");
  sim::Normals n;
  const auto* v = static_cast<const float*>(staging.mapped);
  for (std::size_t k = 0; k < model_.nodes(); ++k) {
    n.x.push_back(v[4 * k]);
    n.y.push_back(v[4 * k + 1]);
    n.z.push_back(v[4 * k + 2]);
  }
  return n;
}

void GpuSolver::set_body_models(std::vector<sim::BodyModel> bodies) {
  if (bodies.size() != model_.bodies.size()) throw InternalError("set_body_models: another number of bodies");
  model_.bodies = std::move(bodies);
  if (contact_) contact_->upload_constants();
}

std::string GpuSolver::identity() const {
  return model_.math == sim::MathMode::exact ? identity_line(ctx_) : std::string();
}

sim::GpuSolverFactory gpu_solver_factory(const Context& ctx) {
  return [&ctx](const sim::WaterModel& model) { return std::make_unique<GpuSolver>(ctx, model); };
}

}  // namespace pond::gpu
