#include "gpu/displacement_readback.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "gpu/shaders.h"
#include "gpu/water_layout.h"


namespace pond::gpu {
namespace {
using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
using DT = vk::DescriptorType;
using BU = vk::BufferUsageFlagBits;
}  // namespace

DisplacementReadback::DisplacementReadback(const Context& ctx, std::size_t pitch, std::size_t stride)
    : ctx_(ctx), pitch_(pitch), stride_(stride) {
  gather_ = create_compute_pipeline(ctx_, water_gather_spirv(), POND_GATHER_BINDINGS, sizeof(GatherPush), {},
                                    "water_gather");
  constexpr std::uint32_t sets = SubmissionRing::kSize + 1;
  const vk::DescriptorPoolSize size{.type = DT::eStorageBuffer, .descriptorCount = sets * POND_GATHER_BINDINGS};
  pool_ = vk::raii::DescriptorPool(ctx_.device(),
                                   vk::DescriptorPoolCreateInfo{.flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                                .maxSets = sets, .poolSizeCount = 1, .pPoolSizes = &size});
  const std::vector<vk::DescriptorSetLayout> layouts(sets, *gather_.set_layout);
  vk::raii::DescriptorSets made(ctx_.device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *pool_, .descriptorSetCount = sets,
                                                                             .pSetLayouts = layouts.data()});
  for (auto& set : made) sets_.push_back(std::move(set));
}

void DisplacementReadback::record_gather(const vk::raii::CommandBuffer& cmd, const Buffer& state, const Buffer& packed,
                                         const core::NodeRuns& runs, std::uint32_t slot) {
  std::vector<GatherRun> list;
  list.reserve(runs.runs().size());
  std::uint32_t at = 0;
  for (const core::NodeRun& r : runs.runs()) {
    const auto first = static_cast<std::uint32_t>(static_cast<std::size_t>(r.row) * pitch_ + static_cast<std::size_t>(r.col0));
    const auto nodes = static_cast<std::uint32_t>(r.col1 - r.col0);
    list.push_back({.first = first, .nodes = nodes, .packed = at, .unused = 0});
    at += nodes;
  }
  const vk::DeviceSize bytes = list.size() * sizeof(GatherRun);
  Buffer& b = runs_[slot];
  if (!*b.buffer || b.size < bytes)
    b = create_buffer(ctx_, std::max<vk::DeviceSize>(bytes, 2 * b.size), BU::eStorageBuffer, MemoryUse::upload,
                      "gather runs " + std::to_string(slot));
  std::memcpy(b.mapped, list.data(), bytes);
  b.flush(ctx_, bytes);
  const vk::DescriptorBufferInfo infos[POND_GATHER_BINDINGS] = {state.whole(), b.whole(), packed.whole()};
  std::array<vk::WriteDescriptorSet, POND_GATHER_BINDINGS> writes;
  for (std::uint32_t k = 0; k < POND_GATHER_BINDINGS; ++k)
    writes[k] = {.dstSet = *sets_[slot], .dstBinding = k, .descriptorCount = 1, .descriptorType = DT::eStorageBuffer,
                 .pBufferInfo = &infos[k]};
  ctx_.device().updateDescriptorSets(writes, nullptr);
  const GatherPush push{.runs = static_cast<std::uint32_t>(list.size()), .stride = static_cast<std::uint32_t>(stride_),
                        .run_nodes = at};
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *gather_.pipeline);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *gather_.layout, 0, *sets_[slot], nullptr);
  cmd.pushConstants<GatherPush>(*gather_.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
  cmd.dispatch(std::min<std::uint32_t>(push.runs, 65535), 3, 1);
}

void DisplacementReadback::unpack(const core::NodeRuns& runs, const float* packed) {
  if (host_.empty()) host_.assign(3 * stride_, 0.0f);
  for (std::size_t c = 0; c < 3; ++c)
    for (const core::NodeRun& r : runs.runs()) {
      const std::size_t n = static_cast<std::size_t>(r.col1 - r.col0);
      const std::size_t first = c * stride_ + static_cast<std::size_t>(r.row) * pitch_ + static_cast<std::size_t>(r.col0);
      std::memcpy(host_.data() + first, packed, n * sizeof(float));
      packed += n;
    }
}

void DisplacementReadback::record(const vk::raii::CommandBuffer& cmd, const Buffer& state, const Submission& s,
                                  std::uint32_t index) {
  copied_[index] = keep_;
  if (!keep_) {
    cmd.copyBuffer(*state.buffer, *s.displacements.buffer,
                   vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = s.displacements.size});
    return;
  }
  if (!keep_->empty()) record_gather(cmd, state, s.displacements, *keep_, index);
}

sim::HostDisplacements DisplacementReadback::host(Submission& s, std::uint32_t index) {
  const std::optional<core::NodeRuns>& copied = copied_[index];
  if (!copied) {  // all of it, read where it landed
    if (!s.displacements_seen) s.displacements.invalidate(ctx_);
    s.displacements_seen = true;
    const auto* u = static_cast<const float*>(s.displacements.mapped);
    return {u, u + stride_, u + 2 * stride_, pitch_};
  }
  if (!s.displacements_seen) {
    s.displacements.invalidate_first(ctx_, 3 * copied->nodes() * sizeof(float));
    unpack(*copied, static_cast<const float*>(s.displacements.mapped));
    held_ = *copied;
    s.displacements_seen = true;
  }
  const float* u = host_.data();
  return {u, u + stride_, u + 2 * stride_, pitch_};
}

bool DisplacementReadback::holds(Submission& s, std::uint32_t index, const core::GridWindow& w) {
  host(s, index);
  return !copied_[index] || held_.covers(w);
}

void DisplacementReadback::bring(Submission& s, std::uint32_t index, const Buffer& state,
                                 std::span<const core::GridWindow> windows) {
  host(s, index);
  if (!copied_[index]) return;  // s copied every node
  const core::NodeRuns missing = core::NodeRuns(windows).minus(held_);
  if (missing.empty()) return;
  const vk::DeviceSize bytes = 3 * missing.nodes() * sizeof(float);
  if (!*fetched_.buffer || fetched_.size < bytes)
    fetched_ = create_buffer(ctx_, std::max<vk::DeviceSize>(bytes, 2 * fetched_.size), BU::eStorageBuffer,
                             MemoryUse::readback, "water displacements brought");
  ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    const vk::MemoryBarrier2 before{.srcStageMask = S::eAllCommands, .srcAccessMask = A::eMemoryWrite,
                                    .dstStageMask = S::eComputeShader, .dstAccessMask = A::eShaderStorageRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &before});
    record_gather(cmd, state, fetched_, missing, SubmissionRing::kSize);
    const vk::MemoryBarrier2 to_host{.srcStageMask = S::eComputeShader, .srcAccessMask = A::eShaderStorageWrite,
                                     .dstStageMask = S::eHost, .dstAccessMask = A::eHostRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
  });
  fetched_.invalidate_first(ctx_, bytes);
  unpack(missing, static_cast<const float*>(fetched_.mapped));
  held_.add(missing);
}

}  // namespace pond::gpu
