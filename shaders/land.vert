#version 460
// The land around and inside the pond: shore, islands and the pool's rim walls (LandVertex), lit
// here, per vertex: the ground colour, grassy on the flat tops, diffuse sun plus sky ambient, darker
// where the walls go down towards the (wet) floor. Per vertex gives the per-pixel result: every
// face is flat and the wetness is linear between the heights the mesh is cut at (see
// kLandWetAtRest), so the light is linear across each triangle, and interpolation reproduces it.
// land.frag adds only a procedural texture (a brightness factor) on top.
// POND_LAND_MIRROR (land_mirror.vert): the land mirrored about the water's rest plane y = 0, for
// the planar reflection (render/reflection_pass.h), drawn from the mesh's walls above the water
// (view::mirrored_walls), so nothing below the water is reflected and no fragment is discarded.
#extension GL_GOOGLE_include_directive : require

#include "shared/water_render.h"

layout(std140, set = 0, binding = POND_RENDER_BINDING_FRAME) uniform Frame { WaterFrame f; };

layout(location = 0) in vec4 in_position;
layout(location = 1) in vec4 in_normal;
layout(location = 0) out vec3 out_color;      // linear, before finish_color
layout(location = 1) out vec3 out_world;      // for the texture
layout(location = 2) out float out_top;       // 1 on flat tops (grass), 0 on walls
layout(location = 3) out vec3 out_sun_share;  // the sun's part of out_color, which a shadow takes
layout(location = 4) out vec3 out_shadow;     // the point in the sun's shadow map (land.frag)
#ifdef POND_LAND_SUBMERGED
layout(location = 5) flat out float out_thick;  // a wall's depth in the submerged layer (land.frag)
#endif

void main() {
  const vec3 n = normalize(in_normal.xyz);
  const float diffuse = max(dot(n, f.sun.xyz), 0.0);
  const float top = smoothstep(0.7, 0.95, n.y);
  const vec3 grass = vec3(0.12, 0.2, 0.07);
  vec3 albedo = mix(f.ground.rgb, grass, top);
  const float wet =
      clamp(kLandWetAtRest - in_position.y / max(POND_FRAME_LAND_HEIGHT(f), 1e-3), 0.0, 1.0);
  albedo *= 1.0 - 0.45 * wet * (1.0 - top);
  const vec3 ambient = f.sky.rgb * (0.25 + 0.15 * n.y);
  const vec3 sun = 0.85 * diffuse * vec3(1.0, 0.96, 0.9);
  out_color = albedo * (ambient + sun);
  out_sun_share = sun / max(ambient + sun, vec3(1e-6));
  out_shadow = (f.shadow * vec4(in_position.xyz, 1.0)).xyz;
  out_world = in_position.xyz;
  out_top = top;
#ifdef POND_LAND_MIRROR
  gl_Position = f.view_proj * vec4(in_position.x, -in_position.y, in_position.z, 1.0);
#else
  // `precise`: the same position with and without shadows, as water.vert's.
  precise vec4 position = f.view_proj * vec4(in_position.xyz, 1.0);
  gl_Position = position;
#endif
#ifdef POND_LAND_SUBMERGED
  // The submerged layer holds what a ray can enter: a wall seen from behind (the island's far
  // side, through its top) is left out, all three corners of it outside the clip volume (a wall's
  // corners share its plane, so they agree).
  if (dot(n, f.eye.xyz - in_position.xyz) <= 0.0) gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
  // A ray enters an island through a wall it sees, so the layer need only call the wall solid for
  // a march step behind its face (water.frag: at most 0.38 floor depths), not the island's width.
  out_thick = 0.5 * POND_FRAME_FLOOR_DEPTH(f) + 0.5;
#endif
}
