#include "render/layer_target.h"

#include "render/frame_constants.h"

namespace pond::render {
namespace {

using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;

vk::ImageMemoryBarrier2 barrier(vk::Image image, vk::ImageAspectFlags aspect, vk::ImageLayout from, vk::ImageLayout to,
                                vk::PipelineStageFlags2 src_stage, vk::AccessFlags2 src_access,
                                vk::PipelineStageFlags2 dst_stage, vk::AccessFlags2 dst_access) {
  return {.srcStageMask = src_stage, .srcAccessMask = src_access, .dstStageMask = dst_stage, .dstAccessMask = dst_access,
          .oldLayout = from, .newLayout = to, .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
          .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .image = image,
          .subresourceRange = {.aspectMask = aspect, .baseMipLevel = 0, .levelCount = 1, .baseArrayLayer = 0, .layerCount = 1}};
}

}  // namespace

bool ensure_layer_target(const gpu::Context& ctx, LayerTarget& t, vk::Extent2D extent, vk::Format format,
                         const std::string& name) {
  if (*t.color.image && t.color.extent == extent && t.color.format == format) return false;
  using U = vk::ImageUsageFlagBits;
  t.color = create_image(ctx, extent, format, U::eColorAttachment | U::eSampled, vk::ImageAspectFlagBits::eColor,
                         name + " colour");
  t.depth = create_image(ctx, extent, kDepthFormat, U::eDepthStencilAttachment, vk::ImageAspectFlagBits::eDepth,
                         name + " depth");
  return true;
}

std::array<vk::ImageMemoryBarrier2, 2> layer_pass_begin(const LayerTarget& t) {
  // The previous frame's water read of this slot's image finished before the slot was reused (its
  // fence); the fragment-shader stage in the source scope orders the transition after it anyway.
  return {
      barrier(*t.color.image, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eUndefined,
              vk::ImageLayout::eColorAttachmentOptimal, S::eFragmentShader, {}, S::eColorAttachmentOutput,
              A::eColorAttachmentWrite | A::eColorAttachmentRead),
      barrier(*t.depth.image, vk::ImageAspectFlagBits::eDepth, vk::ImageLayout::eUndefined,
              vk::ImageLayout::eDepthAttachmentOptimal, S::eLateFragmentTests, A::eDepthStencilAttachmentWrite,
              S::eEarlyFragmentTests | S::eLateFragmentTests,
              A::eDepthStencilAttachmentRead | A::eDepthStencilAttachmentWrite)};
}

void record_layer_pass(const vk::raii::CommandBuffer& cmd, const LayerTarget& t, const std::function<void()>& draw) {
  const vk::Extent2D extent = t.color.extent;
  const vk::RenderingAttachmentInfo color{
      .imageView = *t.color.view, .imageLayout = vk::ImageLayout::eColorAttachmentOptimal,
      .loadOp = vk::AttachmentLoadOp::eClear, .storeOp = vk::AttachmentStoreOp::eStore,
      .clearValue = vk::ClearValue{.color = {.float32 = std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}}}};
  const vk::RenderingAttachmentInfo depth{
      .imageView = *t.depth.view, .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
      .loadOp = vk::AttachmentLoadOp::eClear, .storeOp = vk::AttachmentStoreOp::eDontCare,
      .clearValue = vk::ClearValue{.depthStencil = {.depth = 1.0f, .stencil = 0}}};
  cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, extent}, .layerCount = 1, .colorAttachmentCount = 1,
                                       .pColorAttachments = &color, .pDepthAttachment = &depth});
  cmd.setViewport(0, vk::Viewport{0, 0, static_cast<float>(extent.width), static_cast<float>(extent.height), 0, 1});
  cmd.setScissor(0, vk::Rect2D{{0, 0}, extent});
  draw();
  cmd.endRendering();
}

vk::ImageMemoryBarrier2 layer_pass_end(const LayerTarget& t) {
  return barrier(*t.color.image, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eColorAttachmentOptimal,
                 vk::ImageLayout::eShaderReadOnlyOptimal, S::eColorAttachmentOutput, A::eColorAttachmentWrite,
                 S::eFragmentShader, A::eShaderSampledRead);
}

vk::ImageMemoryBarrier2 layer_unused(const LayerTarget& t) {
  return barrier(*t.color.image, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eUndefined,
                 vk::ImageLayout::eShaderReadOnlyOptimal, S::eFragmentShader, {}, S::eFragmentShader,
                 A::eShaderSampledRead);
}

}  // namespace pond::render
