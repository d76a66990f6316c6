#include "render/body_pipeline.h"

#include <cstddef>

#include "render/graphics_pipeline.h"
#include "shared/body_render.h"
#include "shared/bodies.h"

namespace pond::render {
namespace {
#include "body_frag.spv.h"
#include "body_mirror_frag.spv.h"
#include "body_mirror_vert.spv.h"
#include "body_submerged_frag.spv.h"
#include "body_vert.spv.h"

namespace sh = shared::body_render;
}  // namespace

BodyPipeline create_body_pipeline(const gpu::Context& ctx, vk::Format color_format, vk::Format depth_format,
                                  BodyView view) {
  const bool mirrored = view == BodyView::mirrored;
  BodyPipeline p;
  const vk::PushConstantRange push{.stageFlags = vk::ShaderStageFlagBits::eVertex, .offset = 0,
                                   .size = sizeof(sh::BodyFrame)};
  p.layout = vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo{.pushConstantRangeCount = 1,
                                                                                 .pPushConstantRanges = &push});
  const vk::VertexInputBindingDescription bindings[] = {
      {.binding = 0, .stride = 4 * sizeof(float), .inputRate = vk::VertexInputRate::eVertex},
      {.binding = 1, .stride = sizeof(sh::BodyInstance), .inputRate = vk::VertexInputRate::eInstance},
      {.binding = 2, .stride = sizeof(shared::BodyState), .inputRate = vk::VertexInputRate::eInstance}};
  constexpr auto f4 = vk::Format::eR32G32B32A32Sfloat;
  const vk::VertexInputAttributeDescription attributes[] = {
      {.location = sh::kBodyAttribPoint, .binding = 0, .format = f4, .offset = 0},
      {.location = sh::kBodyAttribSize, .binding = 1, .format = f4, .offset = offsetof(sh::BodyInstance, size)},
      {.location = sh::kBodyAttribAlbedo, .binding = 1, .format = f4, .offset = offsetof(sh::BodyInstance, albedo)},
      {.location = sh::kBodyAttribCentre, .binding = 2, .format = vk::Format::eR32G32B32Sfloat,
       .offset = offsetof(shared::BodyState, x)}};
  const vk::PipelineVertexInputStateCreateInfo vertex_input{.vertexBindingDescriptionCount = 3,
                                                            .pVertexBindingDescriptions = bindings,
                                                            .vertexAttributeDescriptionCount = 4,
                                                            .pVertexAttributeDescriptions = attributes};
  const vk::PipelineInputAssemblyStateCreateInfo assembly{.topology = vk::PrimitiveTopology::eTriangleList};
  const vk::PipelineRasterizationStateCreateInfo raster{.polygonMode = vk::PolygonMode::eFill,
                                                        .cullMode = vk::CullModeFlagBits::eBack,
                                                        .frontFace = mirrored ? vk::FrontFace::eClockwise
                                                                              : vk::FrontFace::eCounterClockwise,
                                                        .lineWidth = 1.0f};
  const vk::PipelineDepthStencilStateCreateInfo depth{
      .depthTestEnable = VK_TRUE, .depthWriteEnable = VK_TRUE, .depthCompareOp = vk::CompareOp::eLessOrEqual};
  using CC = vk::ColorComponentFlagBits;
  const vk::PipelineColorBlendAttachmentState blend{.colorWriteMask = CC::eR | CC::eG | CC::eB | CC::eA};
  using Spirv = std::span<const std::uint32_t>;
  const Spirv frag = view == BodyView::shadow      ? Spirv()
                     : mirrored                    ? Spirv(pond_spirv_body_mirror_frag)
                     : view == BodyView::submerged ? Spirv(pond_spirv_body_submerged_frag)
                                                   : Spirv(pond_spirv_body_frag);
  const char* name = view == BodyView::shadow      ? "bodies (shadow)"
                     : mirrored                    ? "bodies (reflected)"
                     : view == BodyView::submerged ? "bodies (submerged)"
                                                   : "bodies";
  p.pipeline = create_graphics_pipeline(
      ctx, p.layout, color_format, depth_format,
      {mirrored ? Spirv(pond_spirv_body_mirror_vert) : Spirv(pond_spirv_body_vert), frag, vertex_input, assembly, raster,
       depth, blend, name, mirrored || view == BodyView::submerged});
  return p;
}

}  // namespace pond::render
