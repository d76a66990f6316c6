#version 460
// The sky behind everything: one triangle covering the screen at the far depth (1), drawn last with
// the depth test, so only the pixels nothing else covered run sky.frag. Each corner carries its
// view ray (WaterFrame::ray_*), which is linear in screen position: interpolation is exact.
#extension GL_GOOGLE_include_directive : require

#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(std140, set = 0, binding = POND_RENDER_BINDING_FRAME) uniform Frame { WaterFrame f; };

layout(location = 0) noperspective out vec3 out_ray;
// The frame's constants for sky.frag as flat varyings (see POND_WATER_FLAT_*).
layout(location = 1) flat out vec3 out_sun;
layout(location = 2) flat out vec3 out_sky;
layout(location = 3) flat out vec3 out_horizon;

void main() {
  const vec2 ndc = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2)) * 2.0 - 1.0;
  gl_Position = vec4(ndc, 1.0, 1.0);
  out_ray = f.ray_forward.xyz + ndc.x * f.ray_right.xyz + ndc.y * f.ray_down.xyz;
  out_sun = f.sun.xyz;
  out_sky = f.sky.rgb;
  out_horizon = sky_horizon(f.sky.rgb);
}
