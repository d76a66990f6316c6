#pragma once
// A pass of the frame before the main one, as one part (Granite's render-graph passes, Vulkan-
// Samples' subpasses): it owns what it draws with, says whether this frame has it, declares what it
// writes (and how the passes after it read that) and what it reads of the passes before it, and
// records itself. The frame is a list of them (render/early_passes.cpp); the barriers between them
// come from the declarations alone (record_pass_list), so a new pass is a new FramePass and one
// line in that list, never a barrier edited elsewhere.
#include <any>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "gpu/context.h"
#include "render/barrier_batch.h"
#include "render/frame_context.h"
#include "render/pass_timestamps.h"
#include "render/render_layout.h"

namespace pond::render {

using S2 = vk::PipelineStageFlagBits2;
using A2 = vk::AccessFlagBits2;

// One image or buffer a pass writes, all of it, its old contents not needed: how it writes it and,
// unless it is scratch, how it is read after the pass (by later passes and the main pass).
struct PassWrite {
  vk::Image image = nullptr;  // or
  vk::Buffer buffer = nullptr;
  vk::ImageAspectFlags aspect = vk::ImageAspectFlagBits::eColor;
  vk::ImageLayout layout = vk::ImageLayout::eUndefined;  // an image's, while written
  vk::PipelineStageFlags2 stages;
  vk::AccessFlags2 access;
  bool scratch = false;  // nothing reads it after the pass (a layer's depth)
  vk::ImageLayout read_layout = vk::ImageLayout::eShaderReadOnlyOptimal;
  vk::PipelineStageFlags2 read_stages = S2::eFragmentShader;
  vk::AccessFlags2 read_access = A2::eShaderSampledRead;
};

// One output of an earlier pass this pass reads, at these stages.
struct PassRead {
  vk::Image image = nullptr;  // or
  vk::Buffer buffer = nullptr;
  vk::PipelineStageFlags2 stages;
};

struct PassDeclaration {
  std::vector<PassWrite> writes;
  std::vector<PassRead> reads;
};

// What passes give the water's descriptor set (shared/water_render.h) beyond its own bindings:
// each pass whose output the water reads owns its binding (numbered in its own shared header) and
// writes it every frame, its output or, when off, a stand-in of the same kind.
struct WaterSetWrites {
  void buffer(std::uint32_t binding, const gpu::Buffer& b);
  void image(std::uint32_t binding, vk::Sampler sampler, vk::ImageView view, vk::ImageLayout layout);
  std::deque<vk::DescriptorBufferInfo> buffers;  // deques: the writes point into them
  std::deque<vk::DescriptorImageInfo> images;
  std::vector<vk::WriteDescriptorSet> writes;    // dstSet left for the frame to fill in
};

class FramePass {
 public:
  virtual ~FramePass() = default;
  // Its name: its GPU time's (render/pass_timestamps.h, `pond render --profile`, `pond bench`).
  virtual const char* name() const = 0;
  // Whether this frame has it; a pass that is off declares nothing, records nothing and makes
  // nothing.
  virtual bool enabled(const FrameContext& frame) const = 0;
  // What it writes and reads this frame (called once a frame, before record(), when enabled).
  virtual void declare(const FrameContext& frame, PassDeclaration& d) = 0;
  // Its commands, outside any barrier of its declared resources (record_pass_list places those).
  virtual void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) = 0;

  // For a pass whose output the water draws. The bindings it adds to the water's set (the same
  // every frame; the set layout is made from them once).
  virtual void water_bindings(std::vector<vk::DescriptorSetLayoutBinding>& /*out*/) const {}
  // Every frame, on or off, before the water's set is written (the frame's slot finished): what it
  // needs this frame made and set up; then its bindings' descriptors and its lanes of the frame's
  // uniforms.
  virtual void prepare(const FrameContext& /*frame*/) {}
  virtual void bind_water(const FrameContext& /*frame*/, WaterSetWrites& /*set*/, WaterFrame& /*uniforms*/) {}
  // Images and buffers it made (for PassListTest: none while it was never on).
  virtual std::size_t targets_made() const { return 0; }
  // What it hands a pass of the same name in a frame loop made again for the same grid (the demo's
  // new constraints), and takes from one: empty, nothing.
  virtual std::any carry() { return {}; }
  virtual void adopt(std::any /*carried*/) {}
};

// The barriers that passes declaring `declared` (in recording order) need: every output to its
// written layout in one batch before the passes (with `before`, the frame's other dependencies), a
// new batch only before a pass that reads what a pass since the last batch wrote (that output to
// its read layout there), and every other output to the layout it is read in after them all.
// Fewer, fuller barrier commands: render/barrier_batch.h.
struct PassBarriers {
  std::vector<BarrierBatch> before;  // per pass: recorded before it (empty: none)
  BarrierBatch after;                // after the last
};
PassBarriers plan_pass_barriers(std::span<const PassDeclaration> declared, const vk::MemoryBarrier2& before);

// Records the enabled passes of `passes` in order, each timed as its place in the list, with the
// barriers plan_pass_barriers gives for their declarations; returns which it recorded.
PassSet record_pass_list(const vk::raii::CommandBuffer& cmd, const FrameContext& frame,
                         std::span<FramePass* const> passes, const vk::MemoryBarrier2& before);

}  // namespace pond::render
