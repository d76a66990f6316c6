#include "render/water_pipeline.h"

#include <iterator>
#include <span>
#include <stdexcept>
#include <string>

#include "core/errors.h"
#include "render/graphics_pipeline.h"
#include "render/reflection_pass.h"
#include "render/submerged_pass.h"
#include "render/render_layout.h"
#include "render/render_shaders.h"

namespace pond::render {
namespace {

struct PipelineSpec {
  std::span<const std::uint32_t> vert, frag;
  bool land_vertices = false;  // LandVertex attributes (else vertex pulling, no attributes)
  bool lines = false;          // polygon mode line, depth bias towards the camera, alpha blending
  float depth_bias = 0.0f;     // constant depth bias (not with lines)
  bool depth_write = true;
  bool linear_output = false;  // GraphicsPipelineDesc::linear_output
  bool shadows = false;        // GraphicsPipelineDesc::shadows
  bool caustics = false;       // GraphicsPipelineDesc::caustics
  bool submerged = false;      // GraphicsPipelineDesc::submerged
  // The land's and the water's: "less", so where shadows fall a pixel is shaded once although
  // they are drawn twice there (render/frame_loop.cpp).
  vk::CompareOp depth_compare = vk::CompareOp::eLessOrEqual;
  std::string name;
};

// The shadow-sampling land and water are pulled this many depth units (ULPs near the far plane)
// toward the camera: the plain pipelines drawn after them over the same pixels then fail "less"
// even if a device's two compiled vertex shaders round the position a few ULPs apart (`precise`
// keeps the operations, not necessarily the pipelines' code, the same).
constexpr float kShadowedDepthBias = -4.0f;

vk::raii::Pipeline create(const gpu::Context& ctx, const vk::raii::PipelineLayout& layout, vk::Format color,
                          vk::Format depth, const PipelineSpec& s) {
  const vk::VertexInputBindingDescription binding{.binding = 0, .stride = sizeof(LandVertex),
                                                  .inputRate = vk::VertexInputRate::eVertex};
  const vk::VertexInputAttributeDescription attributes[] = {
      {.location = 0, .binding = 0, .format = vk::Format::eR32G32B32A32Sfloat, .offset = offsetof(LandVertex, position)},
      {.location = 1, .binding = 0, .format = vk::Format::eR32G32B32A32Sfloat, .offset = offsetof(LandVertex, normal)}};
  const vk::PipelineVertexInputStateCreateInfo vertex_input =
      s.land_vertices ? vk::PipelineVertexInputStateCreateInfo{.vertexBindingDescriptionCount = 1,
                                                               .pVertexBindingDescriptions = &binding,
                                                               .vertexAttributeDescriptionCount = 2,
                                                               .pVertexAttributeDescriptions = attributes}
                      : vk::PipelineVertexInputStateCreateInfo{};
  const vk::PipelineInputAssemblyStateCreateInfo assembly{.topology = vk::PrimitiveTopology::eTriangleList};
  // Lines: pulled towards the camera by a bias proportional to the slope, so they win over the
  // surface they lie on without showing through waves in front.
  const vk::PipelineRasterizationStateCreateInfo raster{
      .polygonMode = s.lines ? vk::PolygonMode::eLine : vk::PolygonMode::eFill,
      .cullMode = vk::CullModeFlagBits::eNone,
      .frontFace = vk::FrontFace::eCounterClockwise,
      .depthBiasEnable = s.lines || s.depth_bias != 0.0f ? VK_TRUE : VK_FALSE,
      .depthBiasConstantFactor = s.lines ? -2.0f : s.depth_bias,
      .depthBiasSlopeFactor = s.lines ? -1.5f : 0.0f,
      .lineWidth = 1.0f};
  const vk::PipelineDepthStencilStateCreateInfo depth_state{
      .depthTestEnable = VK_TRUE, .depthWriteEnable = s.lines || !s.depth_write ? VK_FALSE : VK_TRUE,
      .depthCompareOp = s.depth_compare};
  using CC = vk::ColorComponentFlagBits;
  const vk::PipelineColorBlendAttachmentState blend{
      .blendEnable = s.lines ? VK_TRUE : VK_FALSE,
      .srcColorBlendFactor = vk::BlendFactor::eSrcAlpha, .dstColorBlendFactor = vk::BlendFactor::eOneMinusSrcAlpha,
      .colorBlendOp = vk::BlendOp::eAdd,
      .srcAlphaBlendFactor = vk::BlendFactor::eZero, .dstAlphaBlendFactor = vk::BlendFactor::eOne,
      .alphaBlendOp = vk::BlendOp::eAdd,
      .colorWriteMask = CC::eR | CC::eG | CC::eB | CC::eA};
  return create_graphics_pipeline(ctx, layout, color, depth,
                                  {s.vert, s.frag, vertex_input, assembly, raster, depth_state, blend, s.name, s.linear_output,
                                   s.shadows, s.caustics, s.submerged});
}

}  // namespace

WaterPipelines create_water_pipelines(const gpu::Context& ctx, vk::Format color_format, vk::Format depth_format,
                                      std::span<const vk::DescriptorSetLayoutBinding> pass_bindings) {
  WaterPipelines p;
  using SS = vk::ShaderStageFlagBits;
  const vk::DescriptorSetLayoutBinding own[] = {
      {.binding = POND_RENDER_BINDING_FRAME, .descriptorType = vk::DescriptorType::eUniformBuffer,
       .descriptorCount = 1, .stageFlags = SS::eVertex | SS::eFragment},
      {.binding = POND_RENDER_BINDING_STATE, .descriptorType = vk::DescriptorType::eStorageBuffer,
       .descriptorCount = 1, .stageFlags = SS::eVertex},
      {.binding = POND_RENDER_BINDING_NORMALS, .descriptorType = vk::DescriptorType::eStorageBuffer,
       .descriptorCount = 1, .stageFlags = SS::eVertex}};
  static_assert(std::size(own) == POND_RENDER_BINDINGS);
  p.set_bindings.assign(std::begin(own), std::end(own));
  for (const vk::DescriptorSetLayoutBinding& b : pass_bindings) {
    for (const vk::DescriptorSetLayoutBinding& earlier : p.set_bindings)
      if (earlier.binding == b.binding)
        throw InternalError("two bindings numbered " + std::to_string(b.binding) + " in the water's set");
    p.set_bindings.push_back(b);
  }
  p.set_layout = vk::raii::DescriptorSetLayout(
      ctx.device(), vk::DescriptorSetLayoutCreateInfo{.bindingCount = static_cast<std::uint32_t>(p.set_bindings.size()),
                                                      .pBindings = p.set_bindings.data()});
  const vk::DescriptorSetLayout set_layout = *p.set_layout;
  p.layout = vk::raii::PipelineLayout(ctx.device(),
                                      vk::PipelineLayoutCreateInfo{.setLayoutCount = 1, .pSetLayouts = &set_layout});
  p.land = create(ctx, p.layout, color_format, depth_format,
                  {.vert = land_vert_spirv(), .frag = land_frag_spirv(), .land_vertices = true,
                   .depth_compare = vk::CompareOp::eLess, .name = "land"});
  p.land_shadowed = create(ctx, p.layout, color_format, depth_format,
                           {.vert = land_vert_spirv(), .frag = land_frag_spirv(), .land_vertices = true,
                            .depth_bias = kShadowedDepthBias, .shadows = true, .depth_compare = vk::CompareOp::eLess,
                            .name = "land, shadowed"});
  for (std::size_t v = 0; v < WaterPipelines::kWaterVariants; ++v) {
    const bool reflections = v & 1u, caustics = v & 2u, shadows = v & 4u, submerged = v & 8u;
    if (WaterPipelines::water_variant(reflections, caustics, shadows, submerged) != p.waters.size())
      throw InternalError("water pipeline variants out of order");
    const std::string name = std::string("water") + (reflections ? ", reflecting" : "") + (caustics ? ", caustics" : "") +
                             (shadows ? ", shadowed" : "") + (submerged ? ", submerged" : "");
    p.waters.push_back(create(ctx, p.layout, color_format, depth_format,
                              {.vert = water_vert_spirv(),
                               .frag = reflections ? water_reflect_frag_spirv() : water_frag_spirv(),
                               .depth_bias = shadows || submerged ? kShadowedDepthBias : 0.0f, .shadows = shadows,
                               .caustics = caustics, .submerged = submerged, .depth_compare = vk::CompareOp::eLess,
                               .name = name}));
  }
  p.land_mirror = create(ctx, p.layout, kReflectionFormat, depth_format,
                         {.vert = land_mirror_vert_spirv(), .frag = land_mirror_frag_spirv(), .land_vertices = true,
                          .linear_output = true, .name = "land, mirrored"});
  p.land_submerged = create(ctx, p.layout, kSubmergedFormat, depth_format,
                            {.vert = land_submerged_vert_spirv(), .frag = land_submerged_frag_spirv(), .land_vertices = true,
                             .linear_output = true, .name = "land, submerged"});
  p.sky = create(ctx, p.layout, color_format, depth_format,
                 {.vert = sky_vert_spirv(), .frag = sky_frag_spirv(), .depth_write = false, .name = "sky"});
  if (ctx.physical().getFeatures().fillModeNonSolid)
    p.wire = create(ctx, p.layout, color_format, depth_format,
                    {.vert = water_vert_spirv(), .frag = water_wire_frag_spirv(), .lines = true, .name = "water LOD wireframe"});
  return p;
}

}  // namespace pond::render
