#include "render/layer_target.h"

#include "render/frame_constants.h"

namespace pond::render {

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

}  // namespace pond::render
