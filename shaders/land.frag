#version 460
// The land's light comes from land.vert (per vertex, exact on its flat faces), the sun's part
// shaded by the tree's and the bodies' shadow (shared/shadow_sampling.h); here a procedural
// texture (a brightness factor), the tone curve and the target's encoding, which are not linear
// and so stay per pixel. The texture is made of triangle waves, not hashed value noise: llvmpipe
// runs every instruction for every pixel, and the land covers much of the screen.
#extension GL_GOOGLE_include_directive : require

#include "shared/water_render.h"
#include "shared/water_shading.h"
// The mirrored land (POND_LAND_MIRROR: land_mirror.frag, the planar reflection's) and the walls
// under the water (POND_LAND_SUBMERGED: land_submerged.frag, render/submerged_pass.h) never read
// the shadow map: while those layers are drawn the map may be in another pass's layout.
#if defined(POND_LAND_MIRROR) || defined(POND_LAND_SUBMERGED)
#define POND_LAND_LAYER
#else
#include "shared/shadow_sampling.h"
#endif

// Depth tested before shading on every device (no discard, no depth write, no side effects): where
// shadows fall this surface is drawn twice, and the second draw must not shade (frame_loop.cpp).
layout(early_fragment_tests) in;

layout(location = 0) in vec3 in_color;
layout(location = 1) in vec3 in_world;
layout(location = 2) in float in_top;
layout(location = 3) in vec3 in_sun_share;  // read only with shadows, so only then interpolated
layout(location = 4) in vec3 in_shadow;
#ifdef POND_LAND_SUBMERGED
layout(location = 5) flat in float in_thick;  // land.vert
#endif
#ifdef POND_LAND_SUBMERGED
layout(location = 0) out uvec2 out_layer;  // render/submerged_pass.h
#else
layout(location = 0) out vec4 out_color;
#endif

float tri(float x) { return abs(fract(x) - 0.5) * 4.0 - 1.0; }

// Grass: drier and lusher patches a few units across; walls: stone courses (rows of blocks offset
// every other course) with a little grain. A factor on the lit colour.
vec3 land_texture(vec3 p, float top) {
  const float patches = tri(p.x * 0.11 + 0.35 * tri(p.z * 0.07)) * tri(p.z * 0.13 + 0.3 * tri(p.x * 0.09));
  const vec3 grass = vec3(1.0) + patches * vec3(0.35, 0.22, 0.05);
  const float course = p.y * 2.5;
  const float along = (p.x + p.z) * 1.25 + 0.5 * step(0.5, fract(course * 0.5));
  const float joint = max(step(0.92, fract(course)), step(0.95, fract(along)));
  const float stone = -0.3 * joint + 0.05 * tri(along * 0.37 + course * 0.61);
  return mix(vec3(1.0 + stone), grass, top);
}

void main() {
  vec3 light = in_color;
#ifndef POND_LAND_LAYER
  if (kShadows) light *= vec3(1.0) - in_sun_share * (1.0 - sun_light(in_shadow));
#endif
#ifdef POND_LAND_SUBMERGED
  out_layer = uvec2(packUnorm4x8(finish_color(light * land_texture(in_world, in_top))),
                    packHalf2x16(vec2(1.0 / gl_FragCoord.w, 1.0 / gl_FragCoord.w + in_thick)));
#else
  out_color = finish_color(light * land_texture(in_world, in_top));
#endif
}
