#include "render/shadow_pass.h"

#include "view/sun_shadow.h"

namespace pond::render {

void ensure_shadow_map(const gpu::Context& ctx, Image& map, std::uint32_t size) {
  if (*map.image && map.extent == vk::Extent2D{size, size}) return;
  using U = vk::ImageUsageFlagBits;
  map = create_image(ctx, {size, size}, kShadowFormat, U::eDepthStencilAttachment | U::eSampled,
                     vk::ImageAspectFlagBits::eDepth, "sun shadow map");
}

void record_shadow_pass(const vk::raii::CommandBuffer& cmd, const Image& map, const std::function<void()>& draw) {
  const vk::RenderingAttachmentInfo depth{
      .imageView = *map.view, .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
      .loadOp = vk::AttachmentLoadOp::eClear, .storeOp = vk::AttachmentStoreOp::eStore,
      .clearValue = vk::ClearValue{.depthStencil = {.depth = 1.0f, .stencil = 0}}};
  const vk::Extent2D extent = map.extent;
  cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, extent}, .layerCount = 1, .pDepthAttachment = &depth});
  cmd.setViewport(0, vk::Viewport{0, 0, static_cast<float>(extent.width), static_cast<float>(extent.height), 0, 1});
  cmd.setScissor(0, vk::Rect2D{{0, 0}, extent});
  draw();
  cmd.endRendering();
}

vk::raii::Sampler create_shadow_sampler(const gpu::Context& ctx) {
  using AM = vk::SamplerAddressMode;
  return vk::raii::Sampler(ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eNearest,
                                                               .minFilter = vk::Filter::eNearest,
                                                               .mipmapMode = vk::SamplerMipmapMode::eNearest,
                                                               .addressModeU = AM::eClampToBorder,
                                                               .addressModeV = AM::eClampToBorder,
                                                               .addressModeW = AM::eClampToBorder,
                                                               .compareEnable = VK_TRUE,
                                                               .compareOp = vk::CompareOp::eLessOrEqual,
                                                               .maxLod = 0.0f,
                                                               .borderColor = vk::BorderColor::eFloatOpaqueWhite});
}

}  // namespace pond::render
