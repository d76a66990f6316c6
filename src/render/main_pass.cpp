#include "render/main_pass.h"

#include <algorithm>
#include <cmath>

#include "render/barrier_batch.h"
#include "render/color_format.h"

namespace pond::render {
namespace {

using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;

vk::Rect2D scissor(const view::PixelRect& r) {
  return {{r.x0, r.y0}, {static_cast<std::uint32_t>(r.x1 - r.x0), static_cast<std::uint32_t>(r.y1 - r.y0)}};
}

// The sky at the horizon (water_shading.h's sky_color at d.y = 0): the background. A clear value
// is stored as given, so for a UNORM target it is sRGB-encoded here, as the shaders encode theirs.
std::array<float, 4> horizon_color(const std::array<double, 3>& z, vk::Format format) {
  auto c = [&](int k) {
    const double linear = std::min(z[k] + (1.0 - z[k]) * 0.55, 1.0);
    if (is_srgb(format)) return static_cast<float>(linear);
    return static_cast<float>(linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055);
  };
  return {c(0), c(1), c(2), 1.0f};
}

}  // namespace

void record_main_pass(const vk::raii::CommandBuffer& cmd, const FrameContext& frame, const FrameTarget& target,
                      const MainPassOptions& options) {
  const FrameData& d = frame.data;
  const view::FramePlan& plan = frame.plan;
  const VisibleDraws& draws = frame.draws;
  const FrameInfo info = frame.info(cmd);
  // The target and the depth buffer to their attachment layouts. The color barrier waits at color
  // output, where the swapchain's acquire semaphore is waited.
  const vk::ImageMemoryBarrier2 images[] = {
      image_barrier(target.image, vk::ImageAspectFlagBits::eColor, target.old_layout,
                     vk::ImageLayout::eColorAttachmentOptimal, S::eColorAttachmentOutput, {}, S::eColorAttachmentOutput,
                     A::eColorAttachmentWrite | A::eColorAttachmentRead),
      image_barrier(*d.depth.image, vk::ImageAspectFlagBits::eDepth, vk::ImageLayout::eUndefined,
                     vk::ImageLayout::eDepthAttachmentOptimal, S::eLateFragmentTests, A::eDepthStencilAttachmentWrite,
                     S::eEarlyFragmentTests | S::eLateFragmentTests,
                     A::eDepthStencilAttachmentRead | A::eDepthStencilAttachmentWrite)};
  cmd.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 2, .pImageMemoryBarriers = images});

  const vk::RenderingAttachmentInfo color{
      .imageView = target.view, .imageLayout = vk::ImageLayout::eColorAttachmentOptimal,
      .loadOp = vk::AttachmentLoadOp::eClear, .storeOp = vk::AttachmentStoreOp::eStore,
      .clearValue = vk::ClearValue{.color = {.float32 = horizon_color(options.sky, target.format)}}};
  const vk::RenderingAttachmentInfo depth{
      .imageView = *d.depth.view, .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
      .loadOp = vk::AttachmentLoadOp::eClear, .storeOp = vk::AttachmentStoreOp::eDontCare,
      .clearValue = vk::ClearValue{.depthStencil = {.depth = 1.0f, .stencil = 0}}};
  cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, target.extent}, .layerCount = 1,
                                       .colorAttachmentCount = 1, .pColorAttachments = &color,
                                       .pDepthAttachment = &depth});
  cmd.setViewport(0, vk::Viewport{0, 0, static_cast<float>(target.extent.width),
                                  static_cast<float>(target.extent.height), 0, 1});
  const vk::Rect2D whole{{0, 0}, target.extent};
  cmd.setScissor(0, whole);
  for (PassDrawable* p : frame.drawables) p->draw_occluding(info);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *frame.pipes.layout, 0, *d.set, nullptr);
  // The land and the water: first where a shadow can fall or what is under the water can show
  // (plan.shadow_rects, scissored), each rectangle with the pipeline that samples what it is for
  // (the shadow map, the submerged layer, or both), then everywhere with those that sample neither.
  // Both test depth with "less" before shading, and a pixel the first draw shaded holds a depth the second cannot beat
  // (the same `precise` vertex code, and the first draw's small bias toward the camera:
  // water_pipeline.cpp), so each pixel is shaded once. llvmpipe runs both sides of a per-pixel
  // branch, so only the scissor keeps the fetches off the pixels no shadow reaches; and one full
  // draw, not the rectangles' complement, keeps the vertex work to one pass over the mesh plus,
  // per rectangle, the triangles that can reach it. `effect_pipe`: a rectangle's pipeline (null:
  // none, it is left to the plain draw).
  auto shaded = [&](const vk::raii::Pipeline& plain, auto effect_pipe, const view::IndexRange& all,
                    const std::vector<view::IndexRange>& in_rects) {
    bool covered = false;  // a rectangle is the whole target (a low sun, a caster behind the eye)
    for (std::size_t k = 0; k < plan.shadow_rects.size(); ++k) {
      const vk::raii::Pipeline* pipe = effect_pipe(plan.shadow_rects[k]);
      if (!pipe) continue;
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, **pipe);
      const vk::Rect2D r = scissor(plan.shadow_rects[k]);
      cmd.setScissor(0, r);
      draw_range(cmd, in_rects[k]);
      covered = covered || r == whole;
    }
    cmd.setScissor(0, whole);
    if (covered) return;
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *plain);
    draw_range(cmd, all);
  };
  const WaterPipelines& pipes = frame.pipes;
  const bool shadow = plan.shadow.has_value();
  frame.geometry.bind_land(cmd, frame.slot);
  shaded(pipes.land, [&](const view::PixelRect& r) { return shadow && r.shadowed ? &pipes.land_shadowed : nullptr; },
         draws.land_whole, draws.land_rects);
  frame.geometry.bind_water(cmd, frame.slot, draws.full_mesh);
  shaded(pipes.water_for(options.reflections, options.caustics, false, false),
         [&](const view::PixelRect& r) {
           return &pipes.water_for(options.reflections, options.caustics, shadow && r.shadowed,
                                   options.submerged && r.submerged);
         },
         draws.water_whole, draws.water_rects);
  if (options.wireframe && *pipes.wire) {
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipes.wire);
    draw_range(cmd, draws.water_whole);
  }
  for (PassDrawable* p : frame.drawables) p->draw(info);
  // Last, so only where nothing is; the drawables bound sets of their own.
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipes.layout, 0, *d.set, nullptr);
  cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipes.sky);
  cmd.draw(30, 1, 0, 0);  // sky.vert's box
  cmd.endRendering();

  // The image to its final layout; and later submissions' compute and copies (the next steps, an
  // upload of a new state) must not overwrite the state, normals or bodies while this pass (or the
  // caustics pass) reads them (write-after-read: an execution dependency).
  const bool present = target.final_layout == vk::ImageLayout::ePresentSrcKHR;
  const vk::ImageMemoryBarrier2 end_image = image_barrier(
      target.image, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eColorAttachmentOptimal, target.final_layout,
      S::eColorAttachmentOutput, A::eColorAttachmentWrite, present ? S::eNone : S::eCopy,
      present ? A::eNone : A::eTransferRead);
  const vk::MemoryBarrier2 vertex_to_compute{
      .srcStageMask = S::eVertexShader | S::eVertexAttributeInput | S::eComputeShader,
      .dstStageMask = S::eComputeShader | S::eCopy};
  cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &vertex_to_compute,
                                          .imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &end_image});
}

}  // namespace pond::render
