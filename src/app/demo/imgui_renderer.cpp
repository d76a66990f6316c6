#include "app/demo/imgui_renderer.h"

#include <imgui.h>

#include <cstring>
#include <span>

#include "render/color_format.h"
#include "imgui_frag.spv.h"
#include "imgui_vert.spv.h"

namespace pond::app::demo {
namespace {

struct Push {
  float scale[2];
  float translate[2];
  std::uint32_t srgb_target;
};

vk::raii::ShaderModule module(const gpu::Context& ctx, std::span<const std::uint32_t> words) {
  return vk::raii::ShaderModule(ctx.device(), vk::ShaderModuleCreateInfo{.codeSize = words.size_bytes(), .pCode = words.data()});
}

}  // namespace

ImGuiRenderer::ImGuiRenderer(const gpu::Context& ctx, vk::Format color_format)
    : ctx_(ctx), srgb_target_(render::is_srgb(color_format)) {
  // The font atlas, uploaded once.
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  const vk::Extent2D extent{static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)};
  font_ = render::create_image(ctx, extent, vk::Format::eR8G8B8A8Unorm,
                            vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                            vk::ImageAspectFlagBits::eColor, "imgui font atlas");
  const vk::DeviceSize bytes = vk::DeviceSize(width) * vk::DeviceSize(height) * 4;
  const gpu::Buffer staging = gpu::create_buffer(ctx, bytes, vk::BufferUsageFlagBits::eTransferSrc,
                                                 gpu::MemoryUse::upload, "imgui font staging");
  std::memcpy(staging.mapped, pixels, bytes);
  staging.flush(ctx);
  ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    const vk::ImageSubresourceRange range{vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1};
    vk::ImageMemoryBarrier2 to_dst{.srcStageMask = vk::PipelineStageFlagBits2::eNone,
                                   .dstStageMask = vk::PipelineStageFlagBits2::eCopy,
                                   .dstAccessMask = vk::AccessFlagBits2::eTransferWrite,
                                   .oldLayout = vk::ImageLayout::eUndefined,
                                   .newLayout = vk::ImageLayout::eTransferDstOptimal,
                                   .image = *font_.image, .subresourceRange = range};
    cmd.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &to_dst});
    const vk::BufferImageCopy copy{.imageSubresource = {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                   .imageExtent = {extent.width, extent.height, 1}};
    cmd.copyBufferToImage(*staging.buffer, *font_.image, vk::ImageLayout::eTransferDstOptimal, copy);
    vk::ImageMemoryBarrier2 to_read{.srcStageMask = vk::PipelineStageFlagBits2::eCopy,
                                    .srcAccessMask = vk::AccessFlagBits2::eTransferWrite,
                                    .dstStageMask = vk::PipelineStageFlagBits2::eFragmentShader,
                                    .dstAccessMask = vk::AccessFlagBits2::eShaderSampledRead,
                                    .oldLayout = vk::ImageLayout::eTransferDstOptimal,
                                    .newLayout = vk::ImageLayout::eShaderReadOnlyOptimal,
                                    .image = *font_.image, .subresourceRange = range};
    cmd.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &to_read});
  });

  // Nearest, one level: ImGui places glyphs on whole pixels, so the atlas is read texel for texel
  // and filtering would only cost (llvmpipe samples in software, on every pixel of the panel).
  // Lines are anti-aliased by geometry instead of the atlas's baked line strips, which need a
  // linear filter (ImGuiStyle::AntiAliasedLinesUseTex, cleared where the context is set up).
  sampler_ = vk::raii::Sampler(ctx.device(), vk::SamplerCreateInfo{
                                                 .magFilter = vk::Filter::eNearest,
                                                 .minFilter = vk::Filter::eNearest,
                                                 .mipmapMode = vk::SamplerMipmapMode::eNearest,
                                                 .addressModeU = vk::SamplerAddressMode::eClampToEdge,
                                                 .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                 .addressModeW = vk::SamplerAddressMode::eClampToEdge,
                                                 .maxLod = 0.0f});
  const vk::DescriptorSetLayoutBinding binding{.binding = 0,
                                               .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                                               .descriptorCount = 1,
                                               .stageFlags = vk::ShaderStageFlagBits::eFragment};
  set_layout_ = vk::raii::DescriptorSetLayout(ctx.device(), vk::DescriptorSetLayoutCreateInfo{.bindingCount = 1, .pBindings = &binding});
  const vk::DescriptorPoolSize pool_size{vk::DescriptorType::eCombinedImageSampler, 1};
  pool_ = vk::raii::DescriptorPool(ctx.device(), vk::DescriptorPoolCreateInfo{
                                                     .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                     .maxSets = 1, .poolSizeCount = 1, .pPoolSizes = &pool_size});
  vk::raii::DescriptorSets sets(ctx.device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *pool_, .descriptorSetCount = 1,
                                                                           .pSetLayouts = &*set_layout_});
  set_ = std::move(sets[0]);
  const vk::DescriptorImageInfo image_info{.sampler = *sampler_, .imageView = *font_.view,
                                           .imageLayout = vk::ImageLayout::eShaderReadOnlyOptimal};
  ctx.device().updateDescriptorSets(vk::WriteDescriptorSet{.dstSet = *set_, .dstBinding = 0, .descriptorCount = 1,
                                                           .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                                                           .pImageInfo = &image_info},
                                    nullptr);
  ImGui::GetIO().Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<VkDescriptorSet>(*set_)));

  const vk::PushConstantRange push{.stageFlags = vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment,
                                   .offset = 0, .size = sizeof(Push)};
  layout_ = vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo{.setLayoutCount = 1, .pSetLayouts = &*set_layout_,
                                                                               .pushConstantRangeCount = 1, .pPushConstantRanges = &push});

  const vk::raii::ShaderModule vert = module(ctx, pond_spirv_imgui_vert);
  const vk::raii::ShaderModule frag = module(ctx, pond_spirv_imgui_frag);
  const vk::PipelineShaderStageCreateInfo stages[] = {
      {.stage = vk::ShaderStageFlagBits::eVertex, .module = *vert, .pName = "main"},
      {.stage = vk::ShaderStageFlagBits::eFragment, .module = *frag, .pName = "main"}};
  const vk::VertexInputBindingDescription vb{.binding = 0, .stride = sizeof(ImDrawVert), .inputRate = vk::VertexInputRate::eVertex};
  const vk::VertexInputAttributeDescription attrs[] = {
      {.location = 0, .binding = 0, .format = vk::Format::eR32G32Sfloat, .offset = offsetof(ImDrawVert, pos)},
      {.location = 1, .binding = 0, .format = vk::Format::eR32G32Sfloat, .offset = offsetof(ImDrawVert, uv)},
      {.location = 2, .binding = 0, .format = vk::Format::eR8G8B8A8Unorm, .offset = offsetof(ImDrawVert, col)}};
  const vk::PipelineVertexInputStateCreateInfo vertex_input{.vertexBindingDescriptionCount = 1, .pVertexBindingDescriptions = &vb,
                                                            .vertexAttributeDescriptionCount = 3, .pVertexAttributeDescriptions = attrs};
  const vk::PipelineInputAssemblyStateCreateInfo assembly{.topology = vk::PrimitiveTopology::eTriangleList};
  const vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
  const vk::PipelineRasterizationStateCreateInfo raster{.polygonMode = vk::PolygonMode::eFill,
                                                        .cullMode = vk::CullModeFlagBits::eNone,
                                                        .frontFace = vk::FrontFace::eCounterClockwise, .lineWidth = 1.0f};
  const vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples = vk::SampleCountFlagBits::e1};
  // Before the scene (draw_occluding), in draw order, writing the nearest depth (z = 0): the scene's
  // fragments behind the panel then fail their depth test before they are shaded.
  const vk::PipelineDepthStencilStateCreateInfo depth{.depthTestEnable = VK_TRUE, .depthWriteEnable = VK_TRUE,
                                                      .depthCompareOp = vk::CompareOp::eAlways};
  const vk::PipelineColorBlendAttachmentState blend_attachment{
      .blendEnable = VK_TRUE,
      .srcColorBlendFactor = vk::BlendFactor::eSrcAlpha,
      .dstColorBlendFactor = vk::BlendFactor::eOneMinusSrcAlpha,
      .colorBlendOp = vk::BlendOp::eAdd,
      .srcAlphaBlendFactor = vk::BlendFactor::eOne,
      .dstAlphaBlendFactor = vk::BlendFactor::eOneMinusSrcAlpha,
      .alphaBlendOp = vk::BlendOp::eAdd,
      .colorWriteMask = vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                        vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA};
  const vk::PipelineColorBlendStateCreateInfo blend{.attachmentCount = 1, .pAttachments = &blend_attachment};
  const vk::DynamicState dynamic_states[] = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
  const vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = 2, .pDynamicStates = dynamic_states};
  const vk::PipelineRenderingCreateInfo rendering{.colorAttachmentCount = 1, .pColorAttachmentFormats = &color_format,
                                                  .depthAttachmentFormat = render::kDepthFormat};
  pipeline_ = vk::raii::Pipeline(ctx.device(), nullptr,
                                 vk::GraphicsPipelineCreateInfo{.pNext = &rendering, .stageCount = 2, .pStages = stages,
                                                                .pVertexInputState = &vertex_input,
                                                                .pInputAssemblyState = &assembly,
                                                                .pViewportState = &viewport,
                                                                .pRasterizationState = &raster,
                                                                .pMultisampleState = &multisample,
                                                                .pDepthStencilState = &depth,
                                                                .pColorBlendState = &blend,
                                                                .pDynamicState = &dynamic,
                                                                .layout = *layout_});
  ctx.name(pipeline_, "imgui pipeline");
}

void ImGuiRenderer::grow(gpu::Buffer& buffer, vk::DeviceSize bytes, vk::BufferUsageFlags usage, const char* name) {
  if (buffer.size >= bytes) return;
  vk::DeviceSize size = buffer.size ? buffer.size : 64 * 1024;
  while (size < bytes) size *= 2;
  buffer = gpu::create_buffer(ctx_, size, usage, gpu::MemoryUse::upload, name);
}

void ImGuiRenderer::upload(const render::FrameInfo& frame) {
  SlotBuffers& slot = slots_[frame.slot];
  slot.ready = false;
  const ImDrawData* data = ImGui::GetDrawData();
  if (!data || !data->Valid || data->TotalVtxCount == 0) return;
  // The slot's previous draw has finished (the loop waited for it before this frame's passes, and
  // they do not read these buffers): they may be rewritten or replaced.
  grow(slot.vertices, vk::DeviceSize(data->TotalVtxCount) * sizeof(ImDrawVert), vk::BufferUsageFlagBits::eVertexBuffer,
       "imgui vertices");
  grow(slot.indices, vk::DeviceSize(data->TotalIdxCount) * sizeof(ImDrawIdx), vk::BufferUsageFlagBits::eIndexBuffer,
       "imgui indices");
  auto* vertices = static_cast<ImDrawVert*>(slot.vertices.mapped);
  auto* indices = static_cast<ImDrawIdx*>(slot.indices.mapped);
  for (int n = 0; n < data->CmdListsCount; ++n) {
    const ImDrawList* list = data->CmdLists[n];
    std::memcpy(vertices, list->VtxBuffer.Data, list->VtxBuffer.Size * sizeof(ImDrawVert));
    std::memcpy(indices, list->IdxBuffer.Data, list->IdxBuffer.Size * sizeof(ImDrawIdx));
    vertices += list->VtxBuffer.Size;
    indices += list->IdxBuffer.Size;
  }
  slot.vertices.flush(ctx_, vk::DeviceSize(data->TotalVtxCount) * sizeof(ImDrawVert));
  slot.indices.flush(ctx_, vk::DeviceSize(data->TotalIdxCount) * sizeof(ImDrawIdx));
  slot.ready = true;  // flushed where not host-coherent: the submit makes the writes visible
}

void ImGuiRenderer::draw_occluding(const render::FrameInfo& frame) {
  upload(frame);
  const SlotBuffers& slot = slots_[frame.slot];
  const ImDrawData* data = ImGui::GetDrawData();
  if (!slot.ready || !data) return;
  const vk::raii::CommandBuffer& cmd = frame.cmd;
  cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline_);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 0, *set_, nullptr);
  cmd.bindVertexBuffers(0, *slot.vertices.buffer, vk::DeviceSize{0});
  cmd.bindIndexBuffer(*slot.indices.buffer, 0, sizeof(ImDrawIdx) == 2 ? vk::IndexType::eUint16 : vk::IndexType::eUint32);
  const float width = static_cast<float>(frame.extent.width), height = static_cast<float>(frame.extent.height);
  cmd.setViewport(0, vk::Viewport{0, 0, width, height, 0, 1});
  // ImGui lays out in display pixels; scale that onto the target (equal unless a screenshot is larger).
  const float sx = width / data->DisplaySize.x, sy = height / data->DisplaySize.y;
  Push push{};
  push.scale[0] = 2.0f / data->DisplaySize.x;
  push.scale[1] = 2.0f / data->DisplaySize.y;
  push.translate[0] = -1.0f - data->DisplayPos.x * push.scale[0];
  push.translate[1] = -1.0f - data->DisplayPos.y * push.scale[1];
  push.srgb_target = srgb_target_ ? 1u : 0u;
  cmd.pushConstants<Push>(*layout_, vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment, 0, push);
  std::uint32_t vertex_base = 0, index_base = 0;
  for (int n = 0; n < data->CmdListsCount; ++n) {
    const ImDrawList* list = data->CmdLists[n];
    for (const ImDrawCmd& c : list->CmdBuffer) {
      if (c.UserCallback) continue;  // the panel uses none
      const float x0 = std::max(0.0f, (c.ClipRect.x - data->DisplayPos.x) * sx);
      const float y0 = std::max(0.0f, (c.ClipRect.y - data->DisplayPos.y) * sy);
      const float x1 = std::min(width, (c.ClipRect.z - data->DisplayPos.x) * sx);
      const float y1 = std::min(height, (c.ClipRect.w - data->DisplayPos.y) * sy);
      if (x1 <= x0 || y1 <= y0) continue;
      cmd.setScissor(0, vk::Rect2D{{static_cast<std::int32_t>(x0), static_cast<std::int32_t>(y0)},
                                   {static_cast<std::uint32_t>(x1 - x0), static_cast<std::uint32_t>(y1 - y0)}});
      cmd.drawIndexed(c.ElemCount, 1, index_base + c.IdxOffset, static_cast<std::int32_t>(vertex_base + c.VtxOffset), 0);
    }
    vertex_base += static_cast<std::uint32_t>(list->VtxBuffer.Size);
    index_base += static_cast<std::uint32_t>(list->IdxBuffer.Size);
  }
  // Leave the scissor as the loop set it for the scene.
  cmd.setScissor(0, vk::Rect2D{{0, 0}, frame.extent});
}

}  // namespace pond::app::demo
