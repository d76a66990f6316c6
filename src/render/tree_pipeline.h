#pragma once
// The wind tree's graphics pipelines (dynamic rendering into the frame loop's color format and
// depth), sharing one descriptor-set layout (shared/tree_render.h bindings) and the TreeInstance
// push constants:
//  - lines: the skeleton as a line list, unlit (the article's look);
//  - twigs: the level of detail's twig lines (tree/tree_lod.h), lit, lighting the pixels their tubes
//           would (shaders/tree.frag);
//  - tubes: the branches' tubes as triangles, lit, back faces culled (their rings wind counter-clockwise
//           seen from outside: tree_mesh.cpp);
//  - leaves: triangles, lit, no culling (a leaf is seen from both sides).
// Each twice: `direct` for the frame's colour format, and `mirrored` for the planar reflection's
// target (FrameLoop::kReflectionFormat): tree_mirror.vert mirrors the tree about the water's rest
// plane y = 0, which turns the tubes' winding clockwise. And `shadow`: depth only, no fragment shader,
// into the sun's shadow map (render/shadow_pass.h, kShadowFormat) through tree_shadow.vert.
#include <cstdint>
#include <span>

#include "gpu/context.h"

namespace pond::render {

struct TreeMaterialPipelines {
  vk::raii::Pipeline lines = nullptr;
  vk::raii::Pipeline twigs = nullptr;
  vk::raii::Pipeline tubes = nullptr;
  vk::raii::Pipeline leaves = nullptr;
};

struct TreePipelines {
  vk::raii::DescriptorSetLayout set_layout = nullptr;
  vk::raii::PipelineLayout layout = nullptr;
  TreeMaterialPipelines direct, mirrored, shadow;
};

TreePipelines create_tree_pipelines(const gpu::Context& ctx, vk::Format color_format, vk::Format depth_format,
                                    vk::Format mirrored_color_format, vk::Format shadow_format);

// SPIR-V of shaders/tree.vert and tree.frag's bark build (embedded at build time).
std::span<const std::uint32_t> tree_vert_spirv();
std::span<const std::uint32_t> tree_frag_spirv();

}  // namespace pond::render
