#include "gpu/submission_ring.h"

#include <algorithm>

#include "core/errors.h"

namespace pond::gpu {
namespace {
using BU = vk::BufferUsageFlagBits;
}  // namespace

SubmissionRing::SubmissionRing(const Context& ctx, vk::DeviceSize displacement_bytes, vk::DeviceSize body_bytes)
    : ctx_(ctx) {
  pool_ = vk::raii::CommandPool(ctx.device(), vk::CommandPoolCreateInfo{
                                                  .flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                  .queueFamilyIndex = ctx.queue_family()});
  vk::raii::CommandBuffers cmds(ctx.device(), vk::CommandBufferAllocateInfo{.commandPool = *pool_,
                                                                            .level = vk::CommandBufferLevel::ePrimary,
                                                                            .commandBufferCount = kSize});
  for (std::uint32_t k = 0; k < kSize; ++k) {
    Submission& s = entries_[k];
    s.cmd = std::move(cmds[k]);
    s.done = vk::raii::Fence(ctx.device(), vk::FenceCreateInfo{});
    const std::string n = std::to_string(k);
    if (displacement_bytes > 0)
      s.displacements = create_buffer(ctx, displacement_bytes, BU::eTransferDst | BU::eStorageBuffer, MemoryUse::readback,
                                      "water displacements readback " + n);
    if (body_bytes > 0)
      s.bodies = create_buffer(ctx, body_bytes, BU::eTransferDst, MemoryUse::readback, "bodies readback " + n);
    ctx.name(s.cmd, "water compute " + n);
  }
}

void SubmissionRing::finish(Submission& s) {
  if (!s.in_flight) return;
  // A wait even when the fence may have signalled: one call a finished submission, whatever the
  // timing, so the waits a frame makes are counted the same on every run (docs/layer.md).
  if (ctx_.device().waitForFences(*s.done, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
    throw RuntimeError("waiting for the water's compute failed");
  s.in_flight = false;
  finished_ = std::max(finished_, s.serial);
}

Submission& SubmissionRing::begin() {
  Submission& s = entries_[next_];
  finish(s);
  ctx_.device().resetFences(*s.done);
  s.displacements_seen = s.bodies_seen = false;
  s.cmd.reset();
  s.cmd.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  return s;
}

void SubmissionRing::submit() {
  Submission& s = entries_[next_];
  s.cmd.end();
  const vk::CommandBufferSubmitInfo info{.commandBuffer = *s.cmd};
  ctx_.queue().submit2(vk::SubmitInfo2{.commandBufferInfoCount = 1, .pCommandBufferInfos = &info}, *s.done);
  s.in_flight = true;
  s.serial = next_serial_++;
  last_ = static_cast<int>(next_);
  next_ = (next_ + 1) % kSize;
}

Submission* SubmissionRing::finish_last() {
  if (last_ < 0) return nullptr;
  Submission& s = entries_[static_cast<std::size_t>(last_)];
  finish(s);
  return &s;
}

void SubmissionRing::finish_all() {
  for (Submission& s : entries_) finish(s);
}

}  // namespace pond::gpu
