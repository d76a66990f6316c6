// record_pass_list (render/frame_pass.h): the barriers between the frame's passes, from what they
// declare.
#include <algorithm>

#include "render/frame_pass.h"

namespace pond::render {
namespace {

bool same(const PassWrite& w, const PassRead& r) {
  return (w.image && w.image == r.image) || (w.buffer && w.buffer == r.buffer);
}

// An output from its last use before this frame's pass (read by an earlier frame, whose contents
// are not needed) to being written.
void to_written(const PassWrite& w, BarrierBatch& batch) {
  if (w.buffer) {  // written after being read: an execution dependency on the readers
    batch.memory.push_back({.srcStageMask = w.read_stages, .dstStageMask = w.stages, .dstAccessMask = w.access});
    return;
  }
  // An image's earlier readers (or, scratch, its earlier writers) done before it is written again.
  const vk::AccessFlags2 writes = A2::eDepthStencilAttachmentWrite | A2::eColorAttachmentWrite | A2::eShaderStorageWrite;
  batch.images.push_back(image_barrier(w.image, w.aspect, vk::ImageLayout::eUndefined, w.layout,
                                       w.scratch ? w.stages : w.read_stages, w.scratch ? w.access & writes : vk::AccessFlags2{},
                                       w.stages, w.access));
}

// An output from being written to being read (`extra`: the stages of a later pass that reads it too).
void to_read(const PassWrite& w, vk::PipelineStageFlags2 extra, BarrierBatch& batch) {
  if (w.buffer) {
    batch.memory.push_back({.srcStageMask = w.stages, .srcAccessMask = w.access, .dstStageMask = w.read_stages | extra,
                            .dstAccessMask = w.read_access});
    return;
  }
  batch.images.push_back(image_barrier(w.image, w.aspect, w.layout, w.read_layout, w.stages, w.access,
                                       w.read_stages | extra, w.read_access));
}

}  // namespace

PassBarriers plan_pass_barriers(std::span<const PassDeclaration> declared, const vk::MemoryBarrier2& before) {
  PassBarriers out;
  out.before.resize(declared.size());
  if (declared.empty()) {  // no pass: the frame's other dependencies still hold for the main pass
    out.after.memory.push_back(before);
    return out;
  }
  out.before.front().memory.push_back(before);
  std::vector<PassWrite> pending;  // written since the frame began, not yet made readable
  std::size_t open = 0;            // the pass whose batch the next outputs' first barriers join
  for (std::size_t k = 0; k < declared.size(); ++k) {
    for (const PassRead& r : declared[k].reads) {
      const auto w = std::find_if(pending.begin(), pending.end(), [&](const PassWrite& x) { return same(x, r); });
      if (w == pending.end()) continue;
      open = k;
      to_read(*w, r.stages, out.before[k]);
      pending.erase(w);
    }
    for (const PassWrite& w : declared[k].writes) {
      to_written(w, out.before[open]);
      if (!w.scratch) pending.push_back(w);
    }
  }
  for (const PassWrite& w : pending) to_read(w, {}, out.after);
  return out;
}

PassSet record_pass_list(const vk::raii::CommandBuffer& cmd, const FrameContext& frame,
                         std::span<FramePass* const> passes, const vk::MemoryBarrier2& before) {
  std::vector<std::size_t> enabled;  // places in `passes`
  std::vector<PassDeclaration> declared;
  for (std::size_t p = 0; p < passes.size(); ++p)
    if (passes[p]->enabled(frame)) {
      enabled.push_back(p);
      passes[p]->declare(frame, declared.emplace_back());
    }
  PassBarriers barriers = plan_pass_barriers(declared, before);
  for (std::size_t k = 0; k < enabled.size(); ++k) {
    barriers.before[k].record(cmd);
    const PassTimestamps::Scope timed = frame.timestamps.scope(cmd, frame.slot, enabled[k]);
    passes[enabled[k]]->record(cmd, frame);
  }
  barriers.after.record(cmd);
  PassSet recorded(passes.size(), false);
  for (std::size_t p : enabled) recorded[p] = true;
  return recorded;
}

void WaterSetWrites::buffer(std::uint32_t binding, const gpu::Buffer& b) {
  buffers.push_back(b.whole());
  writes.push_back({.dstBinding = binding, .descriptorCount = 1, .descriptorType = vk::DescriptorType::eStorageBuffer,
                    .pBufferInfo = &buffers.back()});
}

void WaterSetWrites::image(std::uint32_t binding, vk::Sampler sampler, vk::ImageView view, vk::ImageLayout layout) {
  images.push_back({.sampler = sampler, .imageView = view, .imageLayout = layout});
  writes.push_back({.dstBinding = binding, .descriptorCount = 1,
                    .descriptorType = vk::DescriptorType::eCombinedImageSampler, .pImageInfo = &images.back()});
}

}  // namespace pond::render
