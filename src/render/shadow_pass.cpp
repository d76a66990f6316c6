#include "render/shadow_pass.h"

#include "view/sun_shadow.h"

namespace pond::render {
namespace {

using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;

vk::ImageMemoryBarrier2 barrier(vk::Image image, vk::ImageLayout from, vk::ImageLayout to, vk::PipelineStageFlags2 src_stage,
                                vk::AccessFlags2 src_access, vk::PipelineStageFlags2 dst_stage, vk::AccessFlags2 dst_access) {
  return {.srcStageMask = src_stage, .srcAccessMask = src_access, .dstStageMask = dst_stage, .dstAccessMask = dst_access,
          .oldLayout = from, .newLayout = to, .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
          .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .image = image,
          .subresourceRange = {.aspectMask = vk::ImageAspectFlagBits::eDepth, .baseMipLevel = 0, .levelCount = 1,
                               .baseArrayLayer = 0, .layerCount = 1}};
}

}  // namespace

void ensure_shadow_map(const gpu::Context& ctx, Image& map, std::uint32_t size) {
  if (*map.image && (size == 0 || map.extent == vk::Extent2D{size, size})) return;
  if (size == 0) size = view::kMinShadowMapSize;
  using U = vk::ImageUsageFlagBits;
  map = create_image(ctx, {size, size}, kShadowFormat, U::eDepthStencilAttachment | U::eSampled,
                     vk::ImageAspectFlagBits::eDepth, "sun shadow map");
}

vk::ImageMemoryBarrier2 shadow_pass_begin(const Image& map) {
  // The previous frame's reads of this slot's map finished before the slot was reused (its fence);
  // the fragment-shader stage in the source scope orders the transition after them anyway.
  return barrier(*map.image, vk::ImageLayout::eUndefined, vk::ImageLayout::eDepthAttachmentOptimal, S::eFragmentShader, {},
                 S::eEarlyFragmentTests | S::eLateFragmentTests, A::eDepthStencilAttachmentRead | A::eDepthStencilAttachmentWrite);
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

vk::ImageMemoryBarrier2 shadow_pass_end(const Image& map) {
  return barrier(*map.image, vk::ImageLayout::eDepthAttachmentOptimal, vk::ImageLayout::eShaderReadOnlyOptimal,
                 S::eLateFragmentTests, A::eDepthStencilAttachmentWrite, S::eFragmentShader, A::eShaderSampledRead);
}

vk::ImageMemoryBarrier2 shadow_map_unused(const Image& map) {
  return barrier(*map.image, vk::ImageLayout::eUndefined, vk::ImageLayout::eShaderReadOnlyOptimal, S::eFragmentShader, {},
                 S::eFragmentShader, A::eShaderSampledRead);
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
