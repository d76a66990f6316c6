#version 460
// The sky past the land's end: a box whose walls stand on the land's outer edge and whose lid is
// high above (WaterFrame::sky_lo, sky_hi), 5 faces, 30 vertices from gl_VertexIndex, drawn last with
// the depth test. Its walls start where the land ends, so llvmpipe rasterizes (and runs sky.frag
// for) only the pixels that show sky; a screen-covering triangle would visit every pixel's depth.
#extension GL_GOOGLE_include_directive : require

#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(std140, set = 0, binding = POND_RENDER_BINDING_FRAME) uniform Frame { WaterFrame f; };

layout(location = 0) out vec3 out_world;
// The frame's constants for sky.frag as flat varyings (see POND_WATER_FLAT_*).
layout(location = 1) flat out vec3 out_eye;
layout(location = 2) flat out vec3 out_sun;
layout(location = 3) flat out vec3 out_sky;
layout(location = 4) flat out vec3 out_horizon;

// The box's corners by bits (x: 1, y: 2, z: 4); its faces as two triangles each: the four walls
// (-z, +x, +z, -x) and the lid. No culling: the camera is inside.
const int kFaces[20] = int[20](0, 1, 3, 2, 1, 5, 7, 3, 5, 4, 6, 7, 4, 0, 2, 6, 2, 3, 7, 6);
const int kQuad[6] = int[6](0, 1, 2, 0, 2, 3);

void main() {
  const int face = gl_VertexIndex / 6;
  const int corner = kFaces[face * 4 + kQuad[gl_VertexIndex % 6]];
  const vec3 p = mix(f.sky_lo.xyz, f.sky_hi.xyz, vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1));
  out_world = p;
  gl_Position = f.view_proj * vec4(p, 1.0);
  out_eye = f.eye.xyz;
  out_sun = f.sun.xyz;
  out_sky = f.sky.rgb;
  out_horizon = sky_horizon(f.sky.rgb);
}
