#version 460
// The land around and inside the pond: shore, islands and the pool's rim walls (LandVertex).
#extension GL_GOOGLE_include_directive : require

#include "shared/water_render.h"

layout(std140, set = 0, binding = POND_RENDER_BINDING_FRAME) uniform Frame { WaterFrame f; };

layout(location = 0) in vec4 in_position;
layout(location = 1) in vec4 in_normal;
layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;

void main() {
  out_world = in_position.xyz;
  out_normal = in_normal.xyz;
  gl_Position = f.view_proj * vec4(in_position.xyz, 1.0);
}
