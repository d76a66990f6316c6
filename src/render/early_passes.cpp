#include "render/early_passes.h"

#include "render/caustics_pass.h"
#include "render/foam_pass.h"
#include "render/frame_pass.h"
#include "render/layer_target.h"
#include "render/reflection_pass.h"
#include "render/render_layout.h"
#include "render/shadow_pass.h"
#include "render/submerged_pass.h"

namespace pond::render {
namespace {

using L = vk::ImageLayout;

// The water's binding `binding` for a layer a pass owns: `image`'s view where this frame draws it,
// else the frame's placeholder, which no pipeline of such a frame samples.
void bind_layer(WaterSetWrites& set, std::uint32_t binding, vk::Sampler sampler, const Image* drawn,
                const Image& placeholder) {
  set.image(binding, sampler, drawn ? *drawn->view : *placeholder.view, L::eShaderReadOnlyOptimal);
}

std::size_t made(const Image& i) { return *i.image ? 1 : 0; }

class Shadow final : public FramePass {
 public:
  Shadow(const gpu::Context& ctx, std::uint32_t slots) : ctx_(ctx), maps_(slots), sampler_(create_shadow_sampler(ctx)) {}
  const char* name() const override { return "shadow"; }
  bool enabled(const FrameContext& frame) const override { return frame.plan.shadow.has_value(); }
  void water_bindings(std::vector<vk::DescriptorSetLayoutBinding>& out) const override {
    out.push_back({.binding = POND_RENDER_BINDING_SHADOW, .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                   .descriptorCount = 1, .stageFlags = vk::ShaderStageFlagBits::eFragment});
  }
  void prepare(const FrameContext& frame) override {
    if (enabled(frame)) ensure_shadow_map(ctx_, maps_[frame.slot], frame.plan.shadow->size);
  }
  void bind_water(const FrameContext& frame, WaterSetWrites& set, WaterFrame& /*uniforms*/) override {
    bind_layer(set, POND_RENDER_BINDING_SHADOW, *sampler_, enabled(frame) ? &maps_[frame.slot] : nullptr,
               frame.placeholders.shadow);
  }
  std::size_t targets_made() const override {
    std::size_t n = 0;
    for (const Image& m : maps_) n += made(m);
    return n;
  }
  void declare(const FrameContext& frame, PassDeclaration& d) override {
    d.writes.push_back({.image = *maps_[frame.slot].image, .aspect = vk::ImageAspectFlagBits::eDepth,
                        .layout = L::eDepthAttachmentOptimal, .stages = S2::eEarlyFragmentTests | S2::eLateFragmentTests,
                        .access = A2::eDepthStencilAttachmentRead | A2::eDepthStencilAttachmentWrite});
  }
  void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) override {
    const Image& map = maps_[frame.slot];
    FrameInfo sun = frame.info(cmd);
    sun.view_proj = frame.plan.shadow->clip.data();
    sun.extent = map.extent;
    record_shadow_pass(cmd, map, [&] {
      for (PassDrawable* p : frame.drawables) p->draw_shadow(sun);
    });
  }

 private:
  const gpu::Context& ctx_;
  std::vector<Image> maps_;  // per slot, made at its first frame with shadows
  vk::raii::Sampler sampler_;
};

// A pass that draws into a layer of its own per slot (render/layer_target.h), which the water
// samples after it: the planar reflection and the submerged layer.
class LayerPass : public FramePass {
 public:
  LayerPass(const gpu::Context& ctx, std::uint32_t slots, std::uint32_t binding, vk::Format format, const char* what)
      : ctx_(ctx), layers_(slots), sampler_(create_reflection_sampler(ctx)), binding_(binding), format_(format),
        what_(what) {}
  void water_bindings(std::vector<vk::DescriptorSetLayoutBinding>& out) const override {
    out.push_back({.binding = binding_, .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                   .descriptorCount = 1, .stageFlags = vk::ShaderStageFlagBits::eFragment});
  }
  void prepare(const FrameContext& frame) override {
    if (enabled(frame)) ensure_layer_target(ctx_, layers_[frame.slot], extent(frame.base.extent), format_, what_);
  }
  void bind_water(const FrameContext& frame, WaterSetWrites& set, WaterFrame& /*uniforms*/) override {
    bind_layer(set, binding_, *sampler_, enabled(frame) ? &layers_[frame.slot].color : nullptr, placeholder(frame));
  }
  std::size_t targets_made() const override {
    std::size_t n = 0;
    for (const LayerTarget& t : layers_) n += made(t.color) + made(t.depth);
    return n;
  }
  void declare(const FrameContext& frame, PassDeclaration& d) override {
    // The colour, read by the water's fragment shader after it; the depth, scratch.
    const LayerTarget& t = layers_[frame.slot];
    d.writes.push_back({.image = *t.color.image, .layout = L::eColorAttachmentOptimal,
                        .stages = S2::eColorAttachmentOutput,
                        .access = A2::eColorAttachmentWrite | A2::eColorAttachmentRead});
    d.writes.push_back({.image = *t.depth.image, .aspect = vk::ImageAspectFlagBits::eDepth,
                        .layout = L::eDepthAttachmentOptimal, .stages = S2::eEarlyFragmentTests | S2::eLateFragmentTests,
                        .access = A2::eDepthStencilAttachmentRead | A2::eDepthStencilAttachmentWrite, .scratch = true});
  }

 protected:
  virtual vk::Extent2D extent(vk::Extent2D frame) const = 0;  // the layer's, for a frame's
  virtual const Image& placeholder(const FrameContext& frame) const = 0;
  const LayerTarget& layer(std::uint32_t slot) const { return layers_[slot]; }

 private:
  const gpu::Context& ctx_;
  std::vector<LayerTarget> layers_;  // per slot, made at its first frame with the layer
  vk::raii::Sampler sampler_;        // nearest: the water reads it with texelFetch
  std::uint32_t binding_;
  vk::Format format_;
  const char* what_;
};

class Reflection final : public LayerPass {
 public:
  Reflection(const gpu::Context& ctx, std::uint32_t slots)
      : LayerPass(ctx, slots, POND_RENDER_BINDING_REFLECTION, kReflectionFormat, "reflection") {}
  const char* name() const override { return "reflection"; }
  bool enabled(const FrameContext& frame) const override { return frame.plan.reflection; }
  void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) override {
    const LayerTarget& target = layer(frame.slot);
    FrameInfo mirrored = frame.info(cmd);
    mirrored.extent = target.color.extent;
    mirrored.pixel_scale = static_cast<float>(mirrored.extent.height) / static_cast<float>(frame.base.extent.height);
    record_layer_pass(cmd, target, [&] {
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *frame.pipes.layout, 0, *frame.data.set, nullptr);
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *frame.pipes.land_mirror);
      frame.geometry.bind_mirrored(cmd, frame.slot);
      draw_range(cmd, frame.draws.mirrored);
      for (PassDrawable* p : frame.drawables) p->draw_reflected(mirrored);
    });
  }

 private:
  vk::Extent2D extent(vk::Extent2D frame) const override { return reflection_extent(frame); }
  const Image& placeholder(const FrameContext& frame) const override { return frame.placeholders.reflection; }
};

class Submerged final : public LayerPass {
 public:
  Submerged(const gpu::Context& ctx, std::uint32_t slots)
      : LayerPass(ctx, slots, POND_RENDER_BINDING_SUBMERGED, kSubmergedFormat, "submerged layer") {}
  const char* name() const override { return "submerged"; }
  bool enabled(const FrameContext& frame) const override { return frame.plan.submerged; }
  void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) override {
    const FrameInfo info = frame.info(cmd);
    record_layer_pass(cmd, layer(frame.slot), [&] {
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *frame.pipes.layout, 0, *frame.data.set, nullptr);
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *frame.pipes.land_submerged);
      frame.geometry.draw_submerged(cmd);
      for (PassDrawable* p : frame.drawables) p->draw_submerged(info);
    });
  }

 private:
  vk::Extent2D extent(vk::Extent2D frame) const override { return frame; }
  const Image& placeholder(const FrameContext& frame) const override { return frame.placeholders.submerged; }
};

}  // namespace

EarlyPasses::EarlyPasses(const gpu::Context& ctx, const sim::WaterModel& model) {
  owned_.push_back(std::make_unique<CausticsPass>(ctx, model, kFramesInFlight));
  owned_.push_back(std::make_unique<FoamPass>(ctx, model, kFramesInFlight));
  owned_.push_back(std::make_unique<Shadow>(ctx, kFramesInFlight));
  owned_.push_back(std::make_unique<Reflection>(ctx, kFramesInFlight));
  owned_.push_back(std::make_unique<Submerged>(ctx, kFramesInFlight));
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
