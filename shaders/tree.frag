#version 460
// Wind tree shading: the line look unlit (the article's), bark and leaves with the water's sun and
// sky (diffuse + sky ambient, the land's model), leaves lit from whichever side faces the camera
// and varied in shade per leaf so the crown is not one flat green.
#extension GL_GOOGLE_include_directive : require

#include "shared/tree_render.h"
#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(std140, set = 0, binding = POND_TREE_BINDING_FRAME) uniform Frame { TreeRenderFrame f; };

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in uvec2 in_material;
layout(location = 0) out vec4 out_color;

void main() {
  if (in_material.x == kTreeMaterialLine) {
    out_color = finish_color(f.line.rgb);
    return;
  }
  vec3 n = normalize(in_normal);
  const bool leaf = in_material.x == kTreeMaterialLeaf;
  if (leaf && dot(n, f.eye.xyz - in_world) < 0.0) n = -n;  // a leaf shows its lit side either way
  const float diffuse = max(dot(n, f.sun.xyz), 0.0);
  const float shade = 0.75 + 0.5 * float(in_material.y) / 255.0;
  const vec3 albedo = leaf ? f.leaf.rgb * shade : f.bark.rgb;
  const vec3 ambient = f.sky.rgb * (0.3 + 0.15 * n.y);
  // Light through a leaf: its far side still glows a little when the sun is behind it.
  const float through = leaf ? 0.25 * max(-dot(n, f.sun.xyz), 0.0) : 0.0;
  out_color = finish_color(albedo * (ambient + (0.85 * diffuse + through) * vec3(1.0, 0.96, 0.9)));
}
