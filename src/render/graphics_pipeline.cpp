#include "render/graphics_pipeline.h"

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
  const vk::raii::ShaderModule vs = module(ctx, d.vert), fs = module(ctx, d.frag);
  // The target's encoding is a specialization constant, not a uniform: llvmpipe would otherwise
  // run the per-pixel pow() of the UNORM branch for every pixel under a mask, sRGB targets
  // included (docs/perf.md). Fragment shaders without a constant ignore it.
  const vk::Bool32 frag_values[] = {is_srgb(color) || d.linear_output ? VK_FALSE : VK_TRUE,
                                     d.caustics ? VK_TRUE : VK_FALSE};
  const vk::SpecializationMapEntry frag_entries[] = {
      {.constantID = POND_SPEC_ENCODE_SRGB, .offset = 0, .size = sizeof(vk::Bool32)},
      {.constantID = POND_SPEC_CAUSTICS, .offset = sizeof(vk::Bool32), .size = sizeof(vk::Bool32)}};
  const vk::SpecializationInfo frag_constants{.mapEntryCount = 2, .pMapEntries = frag_entries,
                                              .dataSize = sizeof frag_values, .pData = frag_values};
  const vk::PipelineShaderStageCreateInfo stages[] = {
      {.stage = vk::ShaderStageFlagBits::eVertex, .module = *vs, .pName = "main"},
      {.stage = vk::ShaderStageFlagBits::eFragment, .module = *fs, .pName = "main",
       .pSpecializationInfo = &frag_constants}};
  const vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
  const vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples = vk::SampleCountFlagBits::e1};
  const vk::PipelineColorBlendStateCreateInfo blending{.attachmentCount = 1, .pAttachments = &d.blend};
  const vk::DynamicState dynamic_states[] = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
  const vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = 2, .pDynamicStates = dynamic_states};
  const vk::PipelineRenderingCreateInfo rendering{.colorAttachmentCount = 1, .pColorAttachmentFormats = &color,
                                                  .depthAttachmentFormat = depth};
  const vk::GraphicsPipelineCreateInfo info{.pNext = &rendering,
                                            .stageCount = 2,
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
