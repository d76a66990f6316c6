#pragma once
// The parts every pond graphics pipeline shares: a vertex and a fragment shader from embedded
// SPIR-V, one viewport and scissor set per frame (dynamic), no multisampling, one color attachment
// and a depth attachment through dynamic rendering (so the same pipeline draws into an offscreen
// image or a swapchain image). Each pipeline file describes only what differs. A depth-only
// pipeline (the sun's shadow map) has colour format eUndefined and may have no fragment shader.
#include <cstdint>
#include <span>
#include <string>

#include "gpu/context.h"

namespace pond::render {

struct GraphicsPipelineDesc {
  std::span<const std::uint32_t> vert, frag;  // SPIR-V
  vk::PipelineVertexInputStateCreateInfo vertex_input;
  vk::PipelineInputAssemblyStateCreateInfo assembly;
  vk::PipelineRasterizationStateCreateInfo raster;
  vk::PipelineDepthStencilStateCreateInfo depth;
  vk::PipelineColorBlendAttachmentState blend;
  std::string name;  // debug name
  // The target holds linear colour whatever its format (the planar reflection, which the water
  // samples): the fragment shader does not encode sRGB (POND_SPEC_ENCODE_SRGB off).
  bool linear_output = false;
  // The fragment shader samples the sun's shadow map (POND_SPEC_SHADOWS, shared/shadow_sampling.h).
  bool shadows = false;
  // The water lights the floor it sees with the caustics map (POND_SPEC_CAUSTICS).
  bool caustics = false;
  // The water shows what the submerged layer holds (POND_SPEC_SUBMERGED, render/submerged_pass.h).
  bool submerged = false;
};

vk::raii::Pipeline create_graphics_pipeline(const gpu::Context& ctx, const vk::raii::PipelineLayout& layout,
                                            vk::Format color, vk::Format depth,
                                            const GraphicsPipelineDesc& desc);

}  // namespace pond::render
