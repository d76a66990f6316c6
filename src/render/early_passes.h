#pragma once
// The frame's passes before the main one, in recording order: the caustics' and the foam's compute
// passes (render/caustics_pass.h, render/foam_pass.h), the sun's shadow map
// (render/shadow_pass.h), the planar reflection (render/reflection_pass.h) and the submerged layer
// (render/submerged_pass.h), each a FramePass (render/frame_pass.h) recorded when the frame's plan
// has it, with the barriers their declarations call for. None reads what another writes, so their
// barriers go in two batches: one before them all (with the compute -> vertex dependency on the
// water's state and normals), one after. A new pass is one more line in the constructor.
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "render/frame_context.h"
#include "render/frame_pass.h"
#include "sim/model.h"

namespace pond::render {

class EarlyPasses {
 public:
  // For the water of `model`; the context must outlive this.
  EarlyPasses(const gpu::Context& ctx, const sim::WaterModel& model);

  std::span<FramePass* const> list() const { return passes_; }
  FramePass* find(std::string_view name) const;  // null: no pass of that name
  // Records the frame's enabled passes; returns which it recorded, by place in list().
  PassSet record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame);

 private:
  std::vector<std::unique_ptr<FramePass>> owned_;
  std::vector<FramePass*> passes_;
};

}  // namespace pond::render
