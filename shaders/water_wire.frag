#version 460
// The LOD wireframe overlay: the water's triangles drawn again as lines (polygon mode line, a small
// depth bias towards the camera), blended over the shaded water.
#extension GL_GOOGLE_include_directive : require

#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(std140, set = 0, binding = POND_RENDER_BINDING_FRAME) uniform Frame { WaterFrame f; };

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec4 in_normal_foam;
layout(location = 0) out vec4 out_color;

void main() {
  out_color = vec4(encode_target(f.wire.rgb), f.wire.a);
}
