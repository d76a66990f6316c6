#include "render/early_passes.h"

#include "render/caustics_pass.h"
#include "render/foam_pass.h"
#include "render/frame_pass.h"
#include "render/shadow_pass.h"
#include "render/submerged_pass.h"

namespace pond::render {
namespace {

using L = vk::ImageLayout;

// A layer's two images written by a pass that draws into them (render/layer_target.h): the colour
// read by the water's fragment shader after it, the depth scratch.
void declare_layer(const LayerTarget& t, PassDeclaration& d) {
  d.writes.push_back({.image = *t.color.image, .layout = L::eColorAttachmentOptimal, .stages = S2::eColorAttachmentOutput,
                      .access = A2::eColorAttachmentWrite | A2::eColorAttachmentRead});
  d.writes.push_back({.image = *t.depth.image, .aspect = vk::ImageAspectFlagBits::eDepth,
                      .layout = L::eDepthAttachmentOptimal, .stages = S2::eEarlyFragmentTests | S2::eLateFragmentTests,
                      .access = A2::eDepthStencilAttachmentRead | A2::eDepthStencilAttachmentWrite, .scratch = true});
}

class Shadow final : public FramePass {
 public:
  const char* name() const override { return "shadow"; }
  bool enabled(const FrameContext& frame) const override { return frame.plan.shadow.has_value(); }
  void declare(const FrameContext& frame, PassDeclaration& d) override {
    d.writes.push_back({.image = *frame.data.shadow.image, .aspect = vk::ImageAspectFlagBits::eDepth,
                        .layout = L::eDepthAttachmentOptimal, .stages = S2::eEarlyFragmentTests | S2::eLateFragmentTests,
                        .access = A2::eDepthStencilAttachmentRead | A2::eDepthStencilAttachmentWrite});
  }
  void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) override {
    FrameInfo sun = frame.info(cmd);
    sun.view_proj = frame.plan.shadow->clip.data();
    sun.extent = frame.data.shadow.extent;
    record_shadow_pass(cmd, frame.data.shadow, [&] {
      for (PassDrawable* p : frame.drawables) p->draw_shadow(sun);
    });
  }
};

class Reflection final : public FramePass {
 public:
  const char* name() const override { return "reflection"; }
  bool enabled(const FrameContext& frame) const override { return frame.plan.reflection; }
  void declare(const FrameContext& frame, PassDeclaration& d) override { declare_layer(frame.data.reflection, d); }
  void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) override {
    const FrameData& d = frame.data;
    FrameInfo mirrored = frame.info(cmd);
    mirrored.extent = d.reflection.color.extent;
    mirrored.pixel_scale = static_cast<float>(mirrored.extent.height) / static_cast<float>(frame.base.extent.height);
    record_layer_pass(cmd, d.reflection, [&] {
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *frame.pipes.layout, 0, *d.set, nullptr);
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *frame.pipes.land_mirror);
      frame.geometry.bind_mirrored(cmd, frame.slot);
      draw_range(cmd, frame.draws.mirrored);
      for (PassDrawable* p : frame.drawables) p->draw_reflected(mirrored);
    });
  }
};

class Submerged final : public FramePass {
 public:
  const char* name() const override { return "submerged"; }
  bool enabled(const FrameContext& frame) const override { return frame.plan.submerged; }
  void declare(const FrameContext& frame, PassDeclaration& d) override { declare_layer(frame.data.submerged, d); }
  void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) override {
    const FrameInfo info = frame.info(cmd);
    record_layer_pass(cmd, frame.data.submerged, [&] {
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *frame.pipes.layout, 0, *frame.data.set, nullptr);
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *frame.pipes.land_submerged);
      frame.geometry.draw_submerged(cmd);
      for (PassDrawable* p : frame.drawables) p->draw_submerged(info);
    });
  }
};

}  // namespace

EarlyPasses::EarlyPasses(const gpu::Context& ctx, const sim::WaterModel& model) {
  owned_.push_back(std::make_unique<CausticsPass>(ctx, model, kFramesInFlight));
  owned_.push_back(std::make_unique<FoamPass>(ctx, model, kFramesInFlight));
  owned_.push_back(std::make_unique<Shadow>());
  owned_.push_back(std::make_unique<Reflection>());
  owned_.push_back(std::make_unique<Submerged>());
  for (const std::unique_ptr<FramePass>& p : owned_) passes_.push_back(p.get());
}

FramePass* EarlyPasses::find(std::string_view name) const {
  for (FramePass* p : passes_)
    if (name == p->name()) return p;
  return nullptr;
}

PassSet EarlyPasses::record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) {
  // The solver's writes (compute, and transfers of uploads) and the earlier frames' compute
  // passes' before the vertex shaders (these passes' and the main one's, later in submission
  // order) and this frame's compute passes, which read them (and rewrite their own).
  return record_pass_list(cmd, frame, passes_,
                   {.srcStageMask = S2::eComputeShader | S2::eTransfer,
                    .srcAccessMask = A2::eShaderWrite | A2::eTransferWrite,
                    .dstStageMask = S2::eVertexShader | S2::eVertexAttributeInput | S2::eComputeShader,
                    .dstAccessMask = A2::eShaderRead | A2::eShaderWrite | A2::eVertexAttributeRead});
}

}  // namespace pond::render
