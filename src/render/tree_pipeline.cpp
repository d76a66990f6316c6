#include "render/tree_pipeline.h"

#include "render/graphics_pipeline.h"
#include "shared/tree_render.h"

namespace pond::render {
namespace {
#include "tree_frag.spv.h"
#include "tree_leaf_frag.spv.h"
#include "tree_line_frag.spv.h"
#include "tree_mirror_vert.spv.h"
#include "tree_shadow_vert.spv.h"
#include "tree_twig_frag.spv.h"
#include "tree_vert.spv.h"

namespace sh = shared::tree_wind;

// What differs between the tree's pipelines.
struct Variant {
  vk::PrimitiveTopology topology;
  vk::CullModeFlags cull;
  std::span<const std::uint32_t> frag;  // a variant of tree.frag
  const char* name;
  bool mirrored = false;  // tree_mirror.vert: clockwise front faces
  bool shadow = false;    // tree_shadow.vert, depth only (`frag` unused)
};

vk::raii::Pipeline create(const gpu::Context& ctx, const vk::raii::PipelineLayout& layout, vk::Format color,
                          vk::Format depth, const Variant& variant) {
  using V = sh::TreeMeshVertex;
  const vk::VertexInputBindingDescription binding{.binding = 0, .stride = sizeof(V),
                                                  .inputRate = vk::VertexInputRate::eVertex};
  constexpr auto f3 = vk::Format::eR32G32B32Sfloat;
  constexpr auto branch = offsetof(V, branch);
  const vk::VertexInputAttributeDescription attributes[] = {
      {.location = sh::kTreeAttribPosition, .binding = 0, .format = f3,
       .offset = static_cast<std::uint32_t>(branch + sh::kTreeVertexPosition * sizeof(float))},
      {.location = sh::kTreeAttribWindX, .binding = 0, .format = f3,
       .offset = static_cast<std::uint32_t>(branch + sh::kTreeVertexWindX * sizeof(float))},
      {.location = sh::kTreeAttribWindZ, .binding = 0, .format = f3,
       .offset = static_cast<std::uint32_t>(branch + sh::kTreeVertexWindZ * sizeof(float))},
      {.location = sh::kTreeAttribJitter, .binding = 0, .format = f3,
       .offset = static_cast<std::uint32_t>(branch + sh::kTreeVertexJitter * sizeof(float))},
      {.location = sh::kTreeAttribOffset, .binding = 0, .format = vk::Format::eR32G32B32A32Sfloat,
       .offset = offsetof(V, offset)},
      {.location = sh::kTreeAttribNormal, .binding = 0, .format = vk::Format::eR32G32B32A32Sfloat,
       .offset = offsetof(V, normal)},
      {.location = sh::kTreeAttribInfo, .binding = 0, .format = vk::Format::eR32G32B32A32Uint,
       .offset = offsetof(V, info)}};
  const vk::PipelineVertexInputStateCreateInfo vertex_input{.vertexBindingDescriptionCount = 1,
                                                            .pVertexBindingDescriptions = &binding,
                                                            .vertexAttributeDescriptionCount = 7,
                                                            .pVertexAttributeDescriptions = attributes};
  const vk::PipelineInputAssemblyStateCreateInfo assembly{
      .topology = variant.topology};
  const vk::PipelineRasterizationStateCreateInfo raster{.polygonMode = vk::PolygonMode::eFill,
                                                        .cullMode = variant.cull,
                                                        .frontFace = variant.mirrored ? vk::FrontFace::eClockwise
                                                                                      : vk::FrontFace::eCounterClockwise,
                                                        .lineWidth = 1.0f};
  const vk::PipelineDepthStencilStateCreateInfo depth_state{
      .depthTestEnable = VK_TRUE, .depthWriteEnable = VK_TRUE, .depthCompareOp = vk::CompareOp::eLessOrEqual};
  using CC = vk::ColorComponentFlagBits;
  const vk::PipelineColorBlendAttachmentState blend{.colorWriteMask = CC::eR | CC::eG | CC::eB | CC::eA};
  const std::span<const std::uint32_t> vert = variant.shadow     ? std::span<const std::uint32_t>(pond_spirv_tree_shadow_vert)
                                              : variant.mirrored ? std::span<const std::uint32_t>(pond_spirv_tree_mirror_vert)
                                                                 : tree_vert_spirv();
  return create_graphics_pipeline(ctx, layout, color, depth,
                                  {vert, variant.shadow ? std::span<const std::uint32_t>() : variant.frag, vertex_input,
                                   assembly, raster, depth_state, blend, variant.name, variant.mirrored});
}

}  // namespace

std::span<const std::uint32_t> tree_vert_spirv() { return pond_spirv_tree_vert; }
std::span<const std::uint32_t> tree_frag_spirv() { return pond_spirv_tree_frag; }

TreePipelines create_tree_pipelines(const gpu::Context& ctx, vk::Format color_format, vk::Format depth_format,
                                    vk::Format mirrored_color_format, vk::Format shadow_format) {
  TreePipelines p;
  using SS = vk::ShaderStageFlagBits;
  const vk::DescriptorSetLayoutBinding bindings[] = {
      {.binding = POND_TREE_BINDING_FRAME, .descriptorType = vk::DescriptorType::eUniformBuffer,
       .descriptorCount = 1, .stageFlags = SS::eVertex | SS::eFragment},
      {.binding = POND_TREE_BINDING_SKELETON, .descriptorType = vk::DescriptorType::eStorageBuffer,
       .descriptorCount = 1, .stageFlags = SS::eVertex},
      {.binding = POND_TREE_BINDING_PARENTS, .descriptorType = vk::DescriptorType::eStorageBuffer,
       .descriptorCount = 1, .stageFlags = SS::eVertex}};
  p.set_layout = vk::raii::DescriptorSetLayout(
      ctx.device(), vk::DescriptorSetLayoutCreateInfo{.bindingCount = 3, .pBindings = bindings});
  const vk::DescriptorSetLayout set_layout = *p.set_layout;
  const vk::PushConstantRange push{.stageFlags = SS::eVertex, .offset = 0, .size = sizeof(sh::TreeInstance)};
  p.layout = vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo{.setLayoutCount = 1,
                                                                                 .pSetLayouts = &set_layout,
                                                                                 .pushConstantRangeCount = 1,
                                                                                 .pPushConstantRanges = &push});
  using T = vk::PrimitiveTopology;
  using C = vk::CullModeFlagBits;
  auto materials = [&](vk::Format color, bool mirrored) {
    TreeMaterialPipelines m;
    auto make = [&](T topology, C cull, std::span<const std::uint32_t> frag, const char* name) {
      return create(ctx, p.layout, color, depth_format, {topology, cull, frag, name, mirrored});
    };
    m.lines = make(T::eLineList, C::eNone, pond_spirv_tree_line_frag, mirrored ? "tree lines, mirrored" : "tree lines");
    m.twigs = make(T::eLineList, C::eNone, pond_spirv_tree_twig_frag, mirrored ? "tree twig lines, mirrored" : "tree twig lines");
    // A tube is only ever seen from outside (its open ends sit inside the joints, a twig's width), so
    // its back faces are always hidden: culling them halves what llvmpipe sets up and rasterizes, and
    // its per-triangle cost is what the tree's draw time is made of.
    m.tubes = make(T::eTriangleList, C::eBack, pond_spirv_tree_frag, mirrored ? "tree tubes, mirrored" : "tree tubes");
    m.leaves = make(T::eTriangleList, C::eNone, pond_spirv_tree_leaf_frag, mirrored ? "tree leaves, mirrored" : "tree leaves");
    return m;
  };
  p.direct = materials(color_format, false);
  p.mirrored = materials(mirrored_color_format, true);
  // The shadow map's: the same geometry, depth only (the twig lines cast a texel-wide shadow).
  auto shadow = [&](T topology, C cull, const char* name) {
    return create(ctx, p.layout, vk::Format::eUndefined, shadow_format, {topology, cull, {}, name, false, true});
  };
  p.shadow.lines = shadow(T::eLineList, C::eNone, "tree lines, shadow");
  p.shadow.twigs = shadow(T::eLineList, C::eNone, "tree twig lines, shadow");
  p.shadow.tubes = shadow(T::eTriangleList, C::eBack, "tree tubes, shadow");
  p.shadow.leaves = shadow(T::eTriangleList, C::eNone, "tree leaves, shadow");
  return p;
}

}  // namespace pond::render
