#include "render/foam_pass.h"

#include <cmath>
#include <cstring>
#include <string>

namespace pond::render {
namespace {
#include "foam_comp.spv.h"

using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
using shared::foam::FoamPush;
static_assert(sizeof(FoamPush) == 32 && offsetof(FoamPush, update) == 16);

}  // namespace

FoamPass::FoamPass(const gpu::Context& ctx, const sim::WaterModel& model, std::uint32_t slots)
    : ctx_(ctx), rows_(static_cast<std::uint32_t>(model.rows)), cols_(static_cast<std::uint32_t>(model.cols)),
      slots_(slots) {}

void FoamPass::make() {
  pipeline_ = gpu::create_compute_pipeline(ctx_, pond_spirv_foam_comp, POND_FOAM_BINDINGS, sizeof(FoamPush), {}, "foam");
  const vk::DescriptorPoolSize size{.type = vk::DescriptorType::eStorageBuffer, .descriptorCount = POND_FOAM_BINDINGS * slots_};
  pool_ = vk::raii::DescriptorPool(ctx_.device(), vk::DescriptorPoolCreateInfo{
                                                      .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                      .maxSets = slots_, .poolSizeCount = 1, .pPoolSizes = &size});
  const std::vector<vk::DescriptorSetLayout> layouts(slots_, *pipeline_.set_layout);
  vk::raii::DescriptorSets sets(ctx_.device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *pool_,
                                                                            .descriptorSetCount = slots_,
                                                                            .pSetLayouts = layouts.data()});
  for (vk::raii::DescriptorSet& s : sets) sets_.push_back(std::move(s));
  pushes_.resize(slots_);
  const vk::DeviceSize bytes = vk::DeviceSize{rows_} * cols_ * sizeof(float);
  using U = vk::BufferUsageFlagBits;
  for (std::size_t k = 0; k < buffers_.size(); ++k)
    buffers_[k] = gpu::create_buffer(ctx_, bytes, U::eStorageBuffer | U::eTransferDst | U::eTransferSrc,
                                     gpu::MemoryUse::device, "foam " + std::to_string(k));
  last_ = gpu::create_buffer(ctx_, 4 * bytes, U::eStorageBuffer | U::eTransferDst, gpu::MemoryUse::device,
                             "foam's last displacements");
}

void FoamPass::water_bindings(std::vector<vk::DescriptorSetLayoutBinding>& out) const {
  out.push_back({.binding = POND_FOAM_WATER_BINDING, .descriptorType = vk::DescriptorType::eStorageBuffer,
                 .descriptorCount = 1, .stageFlags = vk::ShaderStageFlagBits::eVertex});
}

void FoamPass::prepare(const FrameContext& frame) {
  const sim::Session& session = frame.base.session;
  if (!enabled(frame)) return skip(session.steps_done());
  update(frame.slot, *frame.water.state, frame.water.stride, frame.water.pitch, session.model(), session.steps_done());
}

void FoamPass::bind_water(const FrameContext& frame, WaterSetWrites& set, WaterFrame& uniforms) {
  const bool on = enabled(frame);
  // Without foam the water reads none: any buffer of a float per node stands in for it.
  set.buffer(POND_FOAM_WATER_BINDING, on ? buffers_[current_] : *frame.water.normals);
  POND_FRAME_FOAM(uniforms) = on ? 1.0f : 0.0f;
}

const gpu::Buffer& FoamPass::update(std::uint32_t slot, const gpu::Buffer& state, std::uint32_t stride,
                                    std::uint32_t pitch, const sim::WaterModel& model, std::int64_t steps) {
  if (!made()) make();
  went_back(steps);
  // The simulated time since the last update: none on the first, nor after the water went back.
  const double elapsed = last_steps_ ? static_cast<double>(steps - *last_steps_) * model.physics.dt : 0.0;
  last_steps_ = steps;
  const gpu::Buffer& from = buffers_[current_];
  current_ ^= 1u;
  const gpu::Buffer& to = buffers_[current_];
  const vk::DescriptorBufferInfo infos[] = {state.whole(), from.whole(), to.whole(), last_.whole()};
  std::array<vk::WriteDescriptorSet, POND_FOAM_BINDINGS> writes;
  for (std::uint32_t b = 0; b < POND_FOAM_BINDINGS; ++b)
    writes[b] = {.dstSet = *sets_[slot], .dstBinding = b, .descriptorCount = 1,
                 .descriptorType = vk::DescriptorType::eStorageBuffer, .pBufferInfo = &infos[b]};
  ctx_.device().updateDescriptorSets(writes, nullptr);
  namespace fs = shared::foam;
  // No stir until there are displacements to move from (the first update, or the first after the
  // water went back, only records them).
  const bool moving = primed_ && elapsed > 0;
  const double wave_speed = std::sqrt(model.physics.stiffness / model.physics.mass);
  pushes_[slot] = {.grid = {rows_, cols_, stride, pitch},
                      .update = {static_cast<float>(std::exp(-elapsed / fs::kFoamFade)),
                                 static_cast<float>(moving ? fs::kFoamRate * elapsed : 0.0),
                                 static_cast<float>(std::min(fs::kFoamSpread * elapsed, 0.5)),
                                 static_cast<float>(moving ? 1.0 / (wave_speed * elapsed) : 0.0)}};
  primed_ = true;
  return to;
}

void FoamPass::skip(std::int64_t steps) {
  went_back(steps);
  primed_ = false;  // the displacements of the last update are stale by the next
}

void FoamPass::went_back(std::int64_t steps) {
  if (!last_steps_ || steps >= *last_steps_) return;
  filled_ = seeded_ = primed_ = false;  // the water went back (reset, an earlier state): no foam
  last_steps_ = steps;
}

void FoamPass::declare(const FrameContext& /*frame*/, PassDeclaration& d) {
  d.writes.push_back({.buffer = *buffers_[current_].buffer, .stages = S::eComputeShader, .access = A::eShaderWrite,
                      .read_stages = S::eVertexShader, .read_access = A::eShaderRead});
}

void FoamPass::record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) {
  const std::uint32_t slot = frame.slot;
  if (!filled_) {  // both buffers zero, or the adopted foam, before the first update reads one
    // After the other frame in flight's update and draw, which may still use them (a reset).
    const vk::MemoryBarrier2 free{.srcStageMask = S::eComputeShader | S::eVertexShader,
                                  .srcAccessMask = A::eShaderWrite,
                                  .dstStageMask = S::eClear | S::eCopy, .dstAccessMask = A::eTransferWrite};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &free});
    cmd.fillBuffer(*last_.buffer, 0, VK_WHOLE_SIZE, 0);
    for (const gpu::Buffer& b : buffers_) {
      if (seeded_)
        cmd.copyBuffer(*seed_.buffer, *b.buffer, vk::BufferCopy{.size = b.size});
      else
        cmd.fillBuffer(*b.buffer, 0, VK_WHOLE_SIZE, 0);
    }
    const vk::MemoryBarrier2 filled{.srcStageMask = S::eTransfer, .srcAccessMask = A::eTransferWrite,
                                    .dstStageMask = S::eComputeShader, .dstAccessMask = A::eShaderRead | A::eShaderWrite};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &filled});
    filled_ = true;
  }
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline_.pipeline);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipeline_.layout, 0, *sets_[slot], nullptr);
  cmd.pushConstants<FoamPush>(*pipeline_.layout, vk::ShaderStageFlagBits::eCompute, 0, pushes_[slot]);
  cmd.dispatch(gpu::group_count(cols_, POND_FOAM_LOCAL_X), rows_, 1);
}

std::any FoamPass::carry() { return Carried{read(), last_steps_}; }

void FoamPass::adopt(std::any carried) {
  const Carried* found = std::any_cast<Carried>(&carried);
  if (!found) return;
  const Carried& c = *found;
  if (filled_ || c.foam.size() != static_cast<std::size_t>(rows_) * cols_) return;
  seed_ = gpu::create_buffer(ctx_, c.foam.size() * sizeof(float), vk::BufferUsageFlagBits::eTransferSrc,
                             gpu::MemoryUse::upload, "foam carried over");
  std::memcpy(seed_.mapped, c.foam.data(), c.foam.size() * sizeof(float));
  seed_.flush(ctx_);
  seeded_ = true;
  last_steps_ = c.steps;
}

std::vector<float> FoamPass::read() {
  std::vector<float> out;
  if (!made()) return out;
  const gpu::Buffer& b = buffers_[current_];
  const gpu::Buffer readback =
      gpu::create_buffer(ctx_, b.size, vk::BufferUsageFlagBits::eTransferDst, gpu::MemoryUse::readback, "foam readback");
  ctx_.device().waitIdle();
  ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    const vk::MemoryBarrier2 before{.srcStageMask = S::eComputeShader, .srcAccessMask = A::eShaderWrite,
                                    .dstStageMask = S::eCopy, .dstAccessMask = A::eTransferRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &before});
    cmd.copyBuffer(*b.buffer, *readback.buffer, vk::BufferCopy{.size = b.size});
    const vk::MemoryBarrier2 to_host{.srcStageMask = S::eCopy, .srcAccessMask = A::eTransferWrite,
                                     .dstStageMask = S::eHost, .dstAccessMask = A::eHostRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
  });
  readback.invalidate(ctx_);
  const auto* f = static_cast<const float*>(readback.mapped);
  out.assign(f, f + b.size / sizeof(float));
  return out;
}

}  // namespace pond::render
