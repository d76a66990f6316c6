#include "render/graphics_pipeline.h"

#include <array>

#include "render/color_format.h"
#include "shared/water_render.h"

namespace pond::render {
namespace {
vk::raii::ShaderModule module(const gpu::Context& ctx, std::span<const std::uint32_t> spirv) {
  return vk::raii::ShaderModule(ctx.device(), vk::ShaderModuleCreateInfo{.codeSize = spirv.size_bytes(),
                                                                         .pCode = spirv.data()});
}
}  // namespace

vk::raii::Pipeline create_graphics_pipeline(const gpu::Context& ctx, const vk::raii::PipelineLayout& layout,
                                            vk::Format color, vk::Format depth,
                                            const GraphicsPipelineDesc& d) {
  const bool has_frag = !d.frag.empty(), has_color = color != vk::Format::eUndefined;
  const vk::raii::ShaderModule vs = module(ctx, d.vert);
  const vk::raii::ShaderModule fs = has_frag ? module(ctx, d.frag) : vk::raii::ShaderModule(nullptr);
  // The target's encoding is a specialization constant, not a uniform: llvmpipe would otherwise
  // run the per-pixel pow() of the UNORM branch for every pixel under a mask, sRGB targets
  // included (docs/perf.md). Fragment shaders without a constant ignore it.
  // Likewise the shadows (shared/shadow_sampling.h), the caustics and the submerged layer: off, the
  // shader holds no code for them.
  const std::array<vk::Bool32, 4> constants{is_srgb(color) || d.linear_output ? VK_FALSE : VK_TRUE,
                                            d.shadows ? VK_TRUE : VK_FALSE, d.caustics ? VK_TRUE : VK_FALSE,
                                            d.submerged ? VK_TRUE : VK_FALSE};
  const vk::SpecializationMapEntry entries[] = {
      {.constantID = POND_SPEC_ENCODE_SRGB, .offset = 0, .size = sizeof(vk::Bool32)},
      {.constantID = POND_SPEC_SHADOWS, .offset = sizeof(vk::Bool32), .size = sizeof(vk::Bool32)},
      {.constantID = POND_SPEC_CAUSTICS, .offset = 2 * sizeof(vk::Bool32), .size = sizeof(vk::Bool32)},
      {.constantID = POND_SPEC_SUBMERGED, .offset = 3 * sizeof(vk::Bool32), .size = sizeof(vk::Bool32)}};
  const vk::SpecializationInfo frag_constants{.mapEntryCount = 4, .pMapEntries = entries,
                                              .dataSize = sizeof constants, .pData = constants.data()};
  const vk::PipelineShaderStageCreateInfo stages[] = {
      {.stage = vk::ShaderStageFlagBits::eVertex, .module = *vs, .pName = "main"},
      {.stage = vk::ShaderStageFlagBits::eFragment, .module = *fs, .pName = "main",
       .pSpecializationInfo = &frag_constants}};
  const vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
  const vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples = vk::SampleCountFlagBits::e1};
  const vk::PipelineColorBlendStateCreateInfo blending{.attachmentCount = has_color ? 1u : 0u, .pAttachments = &d.blend};
  const vk::DynamicState dynamic_states[] = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
  const vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = 2, .pDynamicStates = dynamic_states};
  const vk::PipelineRenderingCreateInfo rendering{.colorAttachmentCount = has_color ? 1u : 0u,
                                                  .pColorAttachmentFormats = has_color ? &color : nullptr,
                                                  .depthAttachmentFormat = depth};
  const vk::GraphicsPipelineCreateInfo info{.pNext = &rendering,
                                            .stageCount = has_frag ? 2u : 1u,
                                            .pStages = stages,
                                            .pVertexInputState = &d.vertex_input,
                                            .pInputAssemblyState = &d.assembly,
                                            .pViewportState = &viewport,
                                            .pRasterizationState = &d.raster,
                                            .pMultisampleState = &multisample,
                                            .pDepthStencilState = &d.depth,
                                            .pColorBlendState = &blending,
                                            .pDynamicState = &dynamic,
                                            .layout = *layout};
  vk::raii::Pipeline pipeline(ctx.device(), nullptr, info);
  ctx.name(pipeline, d.name);
  return pipeline;
}

}  // namespace pond::render
