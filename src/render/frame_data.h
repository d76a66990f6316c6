#pragma once
// One frame in flight's resources (vkguide's FrameData, Vulkan-Samples' RenderFrame): its command
// buffers and fences, its uniforms and descriptor set, its depth buffer (the passes keep their own
// targets per slot: render/frame_pass.h); and the ring of kFramesInFlight of them the frame loop
// uses in turn, so writing frame N+1's uniforms and indices never waits for frame N's draw.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "render/frame_constants.h"
#include "render/frame_target.h"
#include "render/render_target.h"

namespace pond::render {

// What the water's set binds where a frame does not draw the reflection, the shadow map or the
// submerged layer, or has no caustics map yet (their passes are off and made nothing): 1 x 1 images
// in the shader-read layout that the pipelines of such a frame never sample (`reflection`, RGBA8
// UNORM, also stands in for the caustics map, of the same format).
struct Placeholders {
  Image reflection;  // kReflectionFormat
  Image shadow;      // kShadowFormat
  Image submerged;   // kSubmergedFormat
};

struct FrameData {
  vk::raii::CommandBuffer early = nullptr;  // the passes before the main one
  vk::raii::CommandBuffer main = nullptr;   // the main pass
  vk::raii::Fence early_done = nullptr;     // signalled when its last early passes finished
  vk::raii::Fence done = nullptr;           // signalled when its last main pass finished
  gpu::Buffer uniforms;                     // host-visible: WaterFrame
  vk::raii::DescriptorSet set = nullptr;    // the water renderer's set 0 (shared/water_render.h)
  Image depth;
};

// Points `frame`'s descriptor set (shared/water_render.h bindings) at its uniforms and the water's
// `state` and `normals`, and writes `passes` (the passes' own bindings, their dstSet filled in
// here); the frame must be finished.
void write_frame_set(const gpu::Context& ctx, const FrameData& frame, const gpu::Buffer& state,
                     const gpu::Buffer& normals, std::vector<vk::WriteDescriptorSet> passes);

class FrameRing {
 public:
  // Frames whose sets have the layout `set_layout`, of `bindings`.
  FrameRing(const gpu::Context& ctx, vk::DescriptorSetLayout set_layout,
            std::span<const vk::DescriptorSetLayoutBinding> bindings);

  FrameData& operator[](std::uint32_t slot) { return frames_[slot]; }
  const Placeholders& placeholders() const { return placeholders_; }
  const FrameData& operator[](std::uint32_t slot) const { return frames_[slot]; }
  // Until slot's last submissions finished: polls its fences and waits only while they run (in the
  // steady state the frame's one wait, for an earlier frame's compute, has finished them already).
  // What a slot's last frame used is replaced only after this (a target of a new size, the
  // caustics' views of a replaced solver's buffers: CausticsPass::prepare).
  void finish(std::uint32_t slot);
  void finish_all();
  // Makes slot's depth buffer `extent` (the slot must be finished).
  void ensure_depth(std::uint32_t slot, vk::Extent2D extent);
  // Slot's early (main) command buffer reset and begun; submitted with its fence, the main one
  // waiting for the target's semaphore at colour output and signalling its other one.
  const vk::raii::CommandBuffer& begin_early(std::uint32_t slot) { return begin(frames_[slot].early); }
  const vk::raii::CommandBuffer& begin_main(std::uint32_t slot) { return begin(frames_[slot].main); }
  void submit_early(std::uint32_t slot);
  void submit_main(std::uint32_t slot, const FrameTarget& target);

 private:
  static const vk::raii::CommandBuffer& begin(const vk::raii::CommandBuffer& cmd);
  void submit(const vk::raii::CommandBuffer& cmd, const vk::raii::Fence& fence, const FrameTarget* target);

  const gpu::Context& ctx_;
  vk::raii::CommandPool pool_ = nullptr;
  vk::raii::DescriptorPool descriptor_pool_ = nullptr;
  std::array<FrameData, kFramesInFlight> frames_;
  Placeholders placeholders_;
};

}  // namespace pond::render
