#version 460
// The wind tree's vertex shader: the article's bend (Ilyin 2008, SPEC section 2) per vertex,
//     jitter = dot(coeffs, q);  p = pos + wX (wind.x + jitter) + wZ (wind.z + jitter)
// through shared/tree_wind.h's tree_wind_bend (the very function the CPU reference calls), or the
// length-preserving variant walked along the vertex's ancestors (shared/tree_pose.h); then the
// instance's placement and the view-projection. Tube rings and leaf corners carry their skeleton
// vertex's data, so they move with it by its offset. Twig lines (the level of detail's stand-in for
// sub-pixel tubes, tree/tree_lod.h) also pass on how much of a pixel their tube would cover.
// POND_TREE_MIRROR (tree_mirror.vert): the tree mirrored about the water's rest plane y = 0 for the
// planar reflection (render/reflection_pass.h), whose target has inst.pruning.w of the frame's
// pixels per unit length (the twig lines' widths and window positions are scaled by it).
// POND_TREE_SHADOW (tree_shadow.vert): into the sun's shadow map (render/shadow_pass.h), depth only.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require

#include "shared/tree_render.h"
#include "shared/tree_pose.h"

// As the water's exact shaders: x + 0.0 and 0.0 * x are not folded, so the bend keeps the CPU's bits
// (the parity test runs the same functions in tree_pose.comp).
spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve, 32-bit floats

layout(std140, set = 0, binding = POND_TREE_BINDING_FRAME) uniform Frame { TreeRenderFrame f; };
layout(push_constant) uniform Instance { TreeInstance inst; };

layout(location = kTreeAttribPosition) in vec3 in_position;
layout(location = kTreeAttribWindX) in vec3 in_wind_x;
layout(location = kTreeAttribWindZ) in vec3 in_wind_z;
layout(location = kTreeAttribJitter) in vec3 in_jitter;
layout(location = kTreeAttribOffset) in vec4 in_offset;
layout(location = kTreeAttribNormal) in vec4 in_normal;
layout(location = kTreeAttribInfo) in uvec4 in_info;

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out uvec2 out_material;  // material, shade variation
layout(location = 3) out float out_width_px;       // twig lines: the tube's width (pixels)
layout(location = 4) noperspective out vec2 out_axis;  // twig lines: window position (pixels)
layout(location = kTreeFlatEye) flat out vec3 out_eye;
layout(location = kTreeFlatSun) flat out vec3 out_sun;
layout(location = kTreeFlatSky) flat out vec3 out_sky;
layout(location = kTreeFlatAlbedo) flat out vec3 out_albedo;

void main() {
  vec3 p;
  if (inst.wind.bend_mode == kTreeBendKeepLength)
    p = tree_keep_length_vertex(in_info.x, inst.wind);
  else
    p = tree_wind_bend(in_position, in_wind_x, in_wind_z, in_jitter, inst.wind.wind.x, inst.wind.wind.z,
                       inst.wind.twig.xyz);
  // Pruned far leaves are drawn bigger (inst.pruning.x, 1 otherwise), grown about their centres.
  vec3 offset = in_offset.xyz;
  if (in_info.y == kTreeMaterialLeaf && inst.pruning.x != 1.0) {  // unpruned: the offset exactly
    const vec3 centre = unpackSnorm4x8(in_info.w).xyz * inst.pruning.z;
    offset = centre + (offset - centre) * inst.pruning.x;
  }
  out_world = inst.base.xyz + (p + offset) * inst.base.w;
  out_normal = in_normal.xyz;
  out_material = in_info.yz;
#if defined(POND_TREE_MIRROR)
  gl_Position = f.view_proj * vec4(out_world.x, -out_world.y, out_world.z, 1.0);
  const float pixel_scale = inst.pruning.w;
#elif defined(POND_TREE_SHADOW)
  gl_Position = f.light_proj * vec4(out_world, 1.0);
  const float pixel_scale = 1.0;
#else
  gl_Position = f.view_proj * vec4(out_world, 1.0);
  const float pixel_scale = 1.0;
#endif
  // How wide a twig line's tube would be on screen (clip w is the view depth).
  // (Pruned twig lines are drawn wider: inst.pruning.y.)
  out_width_px = in_info.y == kTreeMaterialTwig
                     ? in_offset.w * inst.pruning.y * inst.base.w * f.lod.x * pixel_scale / gl_Position.w
                     : 1.0;
  out_axis = (gl_Position.xy / gl_Position.w * 0.5 + 0.5) * f.lod.yz * pixel_scale;
  out_eye = f.eye.xyz;
  out_sun = f.sun.xyz;
  out_sky = f.sky.rgb;
  out_albedo = in_info.y == kTreeMaterialLine ? f.line.rgb : in_info.y == kTreeMaterialLeaf ? f.leaf.rgb : f.bark.rgb;
}
