#include "render/frame_data.h"

#include <algorithm>
#include <string>

#include "core/errors.h"
#include "render/barrier_batch.h"
#include "render/reflection_pass.h"
#include "render/render_layout.h"
#include "render/shadow_pass.h"
#include "render/submerged_pass.h"

namespace pond::render {
namespace {
using S = vk::PipelineStageFlagBits2;
}  // namespace

FrameRing::FrameRing(const gpu::Context& ctx, vk::DescriptorSetLayout set_layout,
                     std::span<const vk::DescriptorSetLayoutBinding> bindings)
    : ctx_(ctx) {
  pool_ = vk::raii::CommandPool(ctx.device(), vk::CommandPoolCreateInfo{
                                                  .flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                  .queueFamilyIndex = ctx.queue_family()});
  std::vector<vk::DescriptorPoolSize> sizes;  // each binding's, a set per slot
  for (const vk::DescriptorSetLayoutBinding& b : bindings) {
    auto same = std::find_if(sizes.begin(), sizes.end(), [&](const auto& s) { return s.type == b.descriptorType; });
    if (same == sizes.end()) same = sizes.insert(sizes.end(), {.type = b.descriptorType, .descriptorCount = 0});
    same->descriptorCount += b.descriptorCount * kFramesInFlight;
  }
  descriptor_pool_ = vk::raii::DescriptorPool(
      ctx.device(), vk::DescriptorPoolCreateInfo{.flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                 .maxSets = kFramesInFlight,
                                                 .poolSizeCount = static_cast<std::uint32_t>(sizes.size()),
                                                 .pPoolSizes = sizes.data()});
  vk::raii::CommandBuffers cmds(ctx.device(), vk::CommandBufferAllocateInfo{.commandPool = *pool_,
                                                                            .level = vk::CommandBufferLevel::ePrimary,
                                                                            .commandBufferCount = 2 * kFramesInFlight});
  for (std::uint32_t k = 0; k < kFramesInFlight; ++k) {
    FrameData& f = frames_[k];
    f.early = std::move(cmds[2 * k]);
    f.main = std::move(cmds[2 * k + 1]);
    f.early_done = vk::raii::Fence(ctx.device(), vk::FenceCreateInfo{.flags = vk::FenceCreateFlagBits::eSignaled});
    f.done = vk::raii::Fence(ctx.device(), vk::FenceCreateInfo{.flags = vk::FenceCreateFlagBits::eSignaled});
    f.uniforms = gpu::create_buffer(ctx, sizeof(WaterFrame), vk::BufferUsageFlagBits::eUniformBuffer,
                                    gpu::MemoryUse::upload, "water frame uniforms, slot " + std::to_string(k));
    f.set = std::move(vk::raii::DescriptorSets(ctx.device(), vk::DescriptorSetAllocateInfo{
                                                                 .descriptorPool = *descriptor_pool_,
                                                                 .descriptorSetCount = 1, .pSetLayouts = &set_layout})[0]);
  }
  using U = vk::ImageUsageFlagBits;
  const vk::Extent2D one{1, 1};
  placeholders_.reflection = create_image(ctx, one, kReflectionFormat, U::eSampled, vk::ImageAspectFlagBits::eColor,
                                     "placeholder colour");
  placeholders_.shadow = create_image(ctx, one, kShadowFormat, U::eSampled, vk::ImageAspectFlagBits::eDepth,
                                     "placeholder depth");
  placeholders_.submerged = create_image(ctx, one, kSubmergedFormat, U::eSampled, vk::ImageAspectFlagBits::eColor,
                                         "placeholder submerged layer");
  ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {  // never written: only their layout matters
    BarrierBatch to_read;
    for (const Image* i : {&placeholders_.reflection, &placeholders_.shadow, &placeholders_.submerged})
      to_read.images.push_back(image_barrier(
          *i->image, i == &placeholders_.shadow ? vk::ImageAspectFlagBits::eDepth : vk::ImageAspectFlagBits::eColor,
          vk::ImageLayout::eUndefined, vk::ImageLayout::eShaderReadOnlyOptimal, S::eNone, {}, S::eFragmentShader,
          vk::AccessFlagBits2::eShaderSampledRead));
    to_read.record(cmd);
  });
}

void write_frame_set(const gpu::Context& ctx, const FrameData& f, const gpu::Buffer& state, const gpu::Buffer& normals,
                     std::vector<vk::WriteDescriptorSet> passes) {
  using DT = vk::DescriptorType;
  const vk::DescriptorBufferInfo infos[] = {f.uniforms.whole(), state.whole(), normals.whole()};
  std::vector<vk::WriteDescriptorSet> writes = {
      {.dstSet = *f.set, .dstBinding = POND_RENDER_BINDING_FRAME, .descriptorCount = 1,
       .descriptorType = DT::eUniformBuffer, .pBufferInfo = &infos[0]},
      {.dstSet = *f.set, .dstBinding = POND_RENDER_BINDING_STATE, .descriptorCount = 1,
       .descriptorType = DT::eStorageBuffer, .pBufferInfo = &infos[1]},
      {.dstSet = *f.set, .dstBinding = POND_RENDER_BINDING_NORMALS, .descriptorCount = 1,
       .descriptorType = DT::eStorageBuffer, .pBufferInfo = &infos[2]}};
  for (vk::WriteDescriptorSet& w : passes) writes.push_back(w.setDstSet(*f.set));
  ctx.device().updateDescriptorSets(writes, nullptr);
}

void FrameRing::finish(std::uint32_t slot) {
  FrameData& f = frames_[slot];
  if (f.early_done.getStatus() != vk::Result::eSuccess || f.done.getStatus() != vk::Result::eSuccess) {
    const vk::Fence fences[] = {*f.early_done, *f.done};
    if (ctx_.device().waitForFences(fences, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
      throw RuntimeError("waiting for a frame failed");
  }
}

void FrameRing::finish_all() {
  for (std::uint32_t k = 0; k < kFramesInFlight; ++k) finish(k);
}

void FrameRing::ensure_depth(std::uint32_t slot, vk::Extent2D extent) {
  FrameData& f = frames_[slot];
  if (*f.depth.image && f.depth.extent == extent) return;
  f.depth = create_image(ctx_, extent, kDepthFormat, vk::ImageUsageFlagBits::eDepthStencilAttachment,
                         vk::ImageAspectFlagBits::eDepth, "depth, slot " + std::to_string(slot));
}

const vk::raii::CommandBuffer& FrameRing::begin(const vk::raii::CommandBuffer& cmd) {
  cmd.reset();
  cmd.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  return cmd;
}

void FrameRing::submit_early(std::uint32_t slot) { submit(frames_[slot].early, frames_[slot].early_done, nullptr); }
void FrameRing::submit_main(std::uint32_t slot, const FrameTarget& target) {
  submit(frames_[slot].main, frames_[slot].done, &target);
}

void FrameRing::submit(const vk::raii::CommandBuffer& cmd, const vk::raii::Fence& fence, const FrameTarget* target) {
  cmd.end();
  ctx_.device().resetFences(*fence);
  const vk::CommandBufferSubmitInfo cmd_info{.commandBuffer = *cmd};
  const bool wait = target && target->wait_semaphore, signal = target && target->signal_semaphore;
  const vk::SemaphoreSubmitInfo wait_info{.semaphore = wait ? target->wait_semaphore : nullptr,
                                          .stageMask = S::eColorAttachmentOutput};
  const vk::SemaphoreSubmitInfo signal_info{.semaphore = signal ? target->signal_semaphore : nullptr,
                                            .stageMask = S::eAllCommands};
  ctx_.queue().submit2(vk::SubmitInfo2{.waitSemaphoreInfoCount = wait ? 1u : 0u, .pWaitSemaphoreInfos = &wait_info,
                                       .commandBufferInfoCount = 1, .pCommandBufferInfos = &cmd_info,
                                       .signalSemaphoreInfoCount = signal ? 1u : 0u,
                                       .pSignalSemaphoreInfos = &signal_info},
                       *fence);
}

}  // namespace pond::render
