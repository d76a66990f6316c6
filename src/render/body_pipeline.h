#pragma once
// The bodies' graphics pipeline (dynamic rendering into the frame loop's colour format and depth):
// the unit sphere (binding 0, per vertex) instanced per body (binding 1: its size and colour;
// binding 2: its state, whose centre it is drawn at; both per instance), the frame's
// camera and light as push constants (shared/body_render.h), depth-tested and written, back faces
// culled (a sphere is only seen from outside).
#include "gpu/context.h"

namespace pond::render {

struct BodyPipeline {
  vk::raii::PipelineLayout layout = nullptr;
  vk::raii::Pipeline pipeline = nullptr;
};

enum class BodyView {
  direct,
  mirrored,  // the planar reflection's (body_mirror.vert/.frag: mirrored about y = 0, only what is
             // above the water, clockwise front faces, linear colour)
  submerged,  // the submerged layer's (render/submerged_pass.h; body_submerged.frag: only what is
              // below the water, linear colour, the view depth (clip w) in alpha)
  shadow,    // the sun's shadow map's (render/shadow_pass.h): body.vert, depth only (color_format
             // eUndefined), no fragment shader
};

BodyPipeline create_body_pipeline(const gpu::Context& ctx, vk::Format color_format, vk::Format depth_format,
                                  BodyView view = BodyView::direct);

}  // namespace pond::render
