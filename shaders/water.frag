#version 460
// Water shading. The paper's term is the diffuse one (N.L); what makes it read as water:
//  - a Fresnel (Schlick, f0 = 0.02) mix between what is seen through the water and the sky reflected
//    in it, so it is clear looking down and a mirror at grazing angles;
//  - the refracted view ray continued to the pool floor (flat, view.floor_depth below the rest
//    surface) or, where it leaves the pool's box first, to the rim's walls (tiled): the pattern
//    wobbles with the waves, and the colour tends to the deep water colour with the path length
//    through the water (depth tint, Beer-Lambert absorption);
//  - a sharp specular highlight of the sun.
// The floor is analytic (not a second pass reading a depth buffer): one opaque pass, no sorting.
// POND_WATER_REFLECTIONS (water_reflect.frag): what the surface reflects is the planar reflection
// (render/reflection_pass.h: the land and the tree mirrored about y = 0, at the frame's resolution)
// where it holds something, shifted by the normal's tilt, and the sky where it is transparent.
#extension GL_GOOGLE_include_directive : require

#include "shared/caustics.h"
#include "shared/water_render.h"
#include "shared/water_shading.h"
#include "shared/shadow_sampling.h"

// Depth tested before shading on every device (no discard, no depth write, no side effects): where
// shadows fall this surface is drawn twice, and the second draw must not shade (frame_loop.cpp).
layout(early_fragment_tests) in;

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec4 in_normal_foam;  // xyz: the normal; w: the foam here (render/foam_pass.h)
// The frame's constants (water.vert; not the uniform block, see shared/water_render.h).
layout(location = POND_WATER_FLAT_EYE) flat in vec4 in_eye;  // xyz: camera; w: POND_FLAT_INV_SPACING
layout(location = POND_WATER_FLAT_SUN) flat in vec4 in_sun;  // xyz: to the sun; w: POND_FLAT_FLOOR_DEPTH
layout(location = POND_WATER_FLAT_SKY) flat in vec4 in_sky;      // a: POND_FLAT_CAUSTICS
layout(location = POND_WATER_FLAT_WATER) flat in vec4 in_water;  // a: POND_FLAT_CAUSTICS
layout(location = POND_WATER_FLAT_GROUND) flat in vec4 in_ground;  // lit by the sun; a: POND_FLAT_CAUSTICS
layout(location = POND_WATER_FLAT_HORIZON) flat in vec4 in_horizon;  // a: POND_FLAT_CAUSTICS
layout(location = POND_WATER_FLAT_ABSORB) flat in vec3 in_absorb;    // per world unit
layout(location = POND_WATER_FLAT_POOL) flat in vec4 in_pool;  // xy: the far corner, grid units; zw: POND_FLAT_CAUSTICS_SIZE
layout(location = POND_WATER_FLAT_SCREEN) flat in vec3 in_screen;    // WaterFrame::screen.xyz
layout(location = POND_WATER_SHADOW) in vec3 in_shadow;            // this point in the shadow map
layout(location = POND_WATER_FLAT_SHADOW_X) flat in vec4 in_shadow_x;  // WaterFrame::shadow's rows
layout(location = POND_WATER_FLAT_SHADOW_Y) flat in vec4 in_shadow_y;
layout(location = POND_WATER_FLAT_SHADOW_Z) flat in vec4 in_shadow_z;
layout(location = POND_WATER_FLAT_SHADOW_SUN) flat in vec4 in_shadow_sun;  // sunlight in the water; w: floor shade
#ifdef POND_WATER_REFLECTIONS
layout(set = 0, binding = POND_RENDER_BINDING_REFLECTION) uniform sampler2D reflection;
#endif
layout(set = 0, binding = POND_CAUSTICS_WATER_BINDING) uniform sampler2D caustics;
layout(constant_id = POND_SPEC_CAUSTICS) const bool kCaustics = false;
layout(set = 0, binding = POND_RENDER_BINDING_SUBMERGED) uniform usampler2D submerged;
layout(constant_id = POND_SPEC_SUBMERGED) const bool kSubmerged = false;
// Read only where kSubmerged is on, for the refracted ray's clip-space direction, per pixel: every
// flat varying is taken (shared/water_render.h), and one interpolated per vertex bent the images
// of what lies under large calm triangles.
layout(std140, set = 0, binding = POND_RENDER_BINDING_FRAME) uniform Frame { WaterFrame f; };
layout(location = 0) out vec4 out_color;

// The pool floor at a world point: sand with soft ripples a few cells across, so refraction shows.
// Triangle waves instead of sines: llvmpipe evaluates every transcendental per pixel in software.
float tri(float x) { return abs(fract(x) - 0.5) * 4.0 - 1.0; }
vec3 floor_color(vec2 xz) {
  const vec2 p = xz * POND_FLAT_INV_SPACING(in_eye);  // world -> grid units
  const float ripple = tri(p.x * 0.21 + 0.27 * tri(p.y * 0.07)) * tri(p.y * 0.17 + 0.21 * tri(p.x * 0.06));
  return in_ground.rgb * (0.85 + 0.15 * ripple);
}

// Foam's texture at a world point, in [0, 1]: soft blotches several cells across (triangle waves
// bent by others, as the floor's ripples, at periods that do not repeat together).
float foam_patches(vec2 xz) {
  const vec2 p = xz * POND_FLAT_INV_SPACING(in_eye);
  const float a = tri(p.x * 0.083 + 0.8 * tri(p.y * 0.061)) * tri(p.y * 0.097 + 0.8 * tri(p.x * 0.053));
  const float b = tri((p.x + p.y) * 0.131 + 0.7 * tri((p.x - p.y) * 0.071));
  return clamp(0.5 + 0.3 * a + 0.2 * b, 0.0, 1.0);
}

// The rim's wall under water at a world point: tiles a grid unit square with dark grout lines.
vec3 wall_color(vec3 p) {
  const vec2 q = vec2(p.x + p.z, p.y) * POND_FLAT_INV_SPACING(in_eye);
  const float grout = max(step(0.9, fract(q.x)), step(0.9, fract(q.y)));
  return in_ground.rgb * (0.75 - 0.3 * grout);
}

// The sun's light at a point of the floor or a submerged wall relative to calm water's, from this
// frame's caustics map (render/caustics_pass.h; shared/caustics.h): one fetch of the texel's four
// corners, interpolated. (texelFetch rather than a nearest textureLod: the same texel, without the
// sampler's coordinate work, which a software rasterizer runs per pixel; the reflection's too.)
// A wall point reads the texel its depth's calm ray offset gives, clamped to the floor's edge
// (approximate: the map is the floor's).
float caustic_light(vec3 p) {
  if (!kCaustics) return 1.0;
  const vec4 place = POND_FLAT_CAUSTICS(in_sky, in_water, in_ground, in_horizon);  // WaterFrame::caustics
  const vec2 uv = p.xz * place.xy + p.y * place.zw;
  const vec2 t = uv * POND_FLAT_CAUSTICS_SIZE(in_pool);
  const vec4 c = texelFetch(caustics, clamp(ivec2(floor(t)), ivec2(0), ivec2(POND_FLAT_CAUSTICS_SIZE(in_pool)) - 1), 0);
  const vec2 f = fract(t);
  return mix(mix(c.r, c.g, f.x), mix(c.b, c.a, f.x), f.y) * kCausticsDecode;
}

// exp(-x) for x >= 0, without exp: llvmpipe evaluates exp per lane and channel in software
// (exp2's range reduction and polynomial for each of the three channels). exp(-x) = exp(-x/8)^8,
// exp(-u) by its cubic Taylor polynomial: absolute error below 6e-4 (a seventh of an 8-bit level),
// and decreasing in x; u is clamped at 1.5, where the cubic is 0.0625 and its 8th power 2e-10:
// as good as 0. (exp(-x/16)^16 would be ten times closer for three more multiplies a channel.)
vec3 exp_neg(vec3 x) {
  const vec3 u = min(x * 0.125, vec3(1.5));
  vec3 e = vec3(1.0) - u * (vec3(1.0) - u * (vec3(0.5) - u * (1.0 / 6.0)));
  e *= e;
  e *= e;
  return e * e;
}

// What the submerged layer (render/submerged_pass.h) shows along the refracted ray t from this
// point, within `path` of it: rgb its colour, a its distance along t (0: nothing). The layer was
// drawn unrefracted, holding each texel's view depths (clip w) where the eye's line enters and
// leaves what it shows, so a point of the ray at s is projected (clip = this pixel's + s * the
// ray's clip direction) and the layer read there: the ray is inside what the texel shows where the
// point's depth lies between the two. Marched in kMarch steps to the floor or wall, then halved
// twice toward the entry.
const int kMarch = 4;
bool submerged_inside(vec3 clip, out vec3 color) {
  const ivec2 size = textureSize(submerged, 0);
  const uvec2 texel = texelFetch(submerged, clamp(ivec2(floor((clip.xy / clip.z * 0.5 + 0.5) * vec2(size))), ivec2(0), size - 1), 0).xy;
  color = unpackUnorm4x8(texel.x).rgb;
  const vec2 depths = unpackHalf2x16(texel.y);
  const float front = depths.x, back = depths.y;
  return front > 0.0 && clip.z >= front && clip.z <= back;
}
vec4 submerged_seen(vec3 t, float path) {
  if (!kSubmerged) return vec4(0.0);
  const float w = 1.0 / gl_FragCoord.w;
  const vec3 here = vec3((gl_FragCoord.xy * in_screen.xy * 2.0 - 1.0) * w, w);
  const vec3 ray = (f.view_proj * vec4(t, 0.0)).xyw;
  const float step = path / float(kMarch);
  float lo = 0.0, hi = -1.0;
  vec3 seen = vec3(0.0), c;
  for (int k = 1; k <= kMarch && hi < 0.0; ++k) {
    if (submerged_inside(here + (step * float(k)) * ray, c)) seen = c, hi = step * float(k);
    else lo = step * float(k);
  }
  if (hi < 0.0) return vec4(0.0);
  for (int k = 0; k < 2; ++k) {
    const float s = 0.5 * (lo + hi);
    if (submerged_inside(here + s * ray, c)) seen = c, hi = s;
    else lo = s;
  }
  return vec4(seen, hi);
}

// The sun's light (shared/shadow_sampling.h) on the surface here (x) and on the floor or wall point
// `hit` seen through it (y): where the sunlight reaching `hit` entered the water, followed back
// along the refracted sun to the rest plane (the casters are all above it).
vec2 water_sun_light(vec3 hit) {
  if (!kShadows) return vec2(1.0);
  const vec4 entry = vec4(hit - in_shadow_sun.xyz * (hit.y / in_shadow_sun.y), 1.0);
  return vec2(sun_light(in_shadow), sun_light(vec3(dot(in_shadow_x, entry), dot(in_shadow_y, entry), dot(in_shadow_z, entry))));
}

void main() {
  vec3 n = normalize(in_normal_foam.xyz);
  const vec3 v = normalize(in_eye.xyz - in_world);
  if (!gl_FrontFacing && dot(n, v) < 0.0) n = -n;  // folded wave crests seen from below
  const vec3 l = in_sun.xyz;

  const float diffuse = max(dot(n, l), 0.0);  // the paper's term
  const float cos_v = clamp(dot(n, v), 0.0, 1.0);
  const float m = 1.0 - cos_v, m2 = m * m;
  const float fresnel = 0.02 + 0.98 * (m2 * m2 * m);  // Schlick, (1 - cos)^5

  // Seen through the water: the refracted ray to the floor (air -> water, 1 / 1.33).
  const vec3 t = refract(-v, n, 1.0 / 1.33);
  const float depth_here = in_world.y + POND_FLAT_FLOOR_DEPTH(in_sun);  // water column under it
  float path = max(depth_here, 0.0) / max(-t.y, 0.08);
  // Where the ray leaves the pool's box [0, cols - 1] x [0, rows - 1] (grid units) before the floor,
  // it meets a rim wall.
  const vec2 start = in_world.xz * POND_FLAT_INV_SPACING(in_eye), dir = t.xz * POND_FLAT_INV_SPACING(in_eye);
  const vec2 room = mix(start, in_pool.xy - start, greaterThan(dir, vec2(0.0)));  // to the wall ahead
  const vec2 exits = max(room, vec2(0.0)) / max(abs(dir), vec2(1e-6));
  const float exit_path = min(exits.x, exits.y);
  const bool wall = exit_path < path;
  path = min(path, exit_path);
  const vec3 hit = in_world + t * path;
  const vec2 sun = water_sun_light(hit);  // the shadows of the tree and the bodies
  const vec3 body = in_water.rgb * (0.35 + 0.65 * diffuse * sun.x);  // scattered light: diffuse-lit water colour
  // The floor's light: the sky's share, and the sun's, focused by the waves and shadowed; or what
  // the submerged layer shows in front of it, lit as it was drawn.
  const vec4 seen = submerged_seen(t, path);
  const vec3 bottom = seen.a > 0.0 ? seen.rgb
                                   : (wall ? wall_color(hit) : floor_color(hit.xz)) * mix(in_shadow_sun.w, caustic_light(hit), sun.y);
  const vec3 transmit = exp_neg(in_absorb * (seen.a > 0.0 ? seen.a : path));
  const vec3 seen_through = bottom * transmit + body * (vec3(1.0) - transmit);

  const vec3 r = reflect(-v, n);
  vec3 reflected = sky_color(in_sky.rgb, in_horizon.rgb, r, l);
#ifdef POND_WATER_REFLECTIONS
  // The mirror image at this pixel, shifted by the surface's tilt (a flat surface: no shift); its
  // alpha is 0 where nothing above the water is mirrored there, and the sky shows instead.
  const vec2 uv = gl_FragCoord.xy * in_screen.xy + n.xz * in_screen.z;
  const ivec2 size = textureSize(reflection, 0);
  const vec4 mirrored = texelFetch(reflection, clamp(ivec2(floor(uv * vec2(size))), ivec2(0), size - 1), 0);
  reflected = mix(reflected, mirrored.rgb, mirrored.a);
#endif
  // The sun's glint, (r.l)^2048 by squaring: a narrow lobe without pow's exp/log.
  float spec = max(dot(r, l), 0.0);
  for (int k = 0; k < 11; ++k) spec *= spec;
  spec *= 3.0 * sun.x;

  vec3 color = mix(seen_through, reflected, fresnel) + spec * vec3(1.0, 0.95, 0.85) * fresnel * 4.0;
  // Foam on top, a rough white lit by the sky and the sun: thin foam shows as patches, thick foam
  // covers (no foam: the colour as is).
  const vec3 foam = vec3(0.92, 0.94, 0.95) * (0.45 + 0.55 * diffuse * sun.x);
  color = mix(color, foam, clamp(in_normal_foam.w * (0.2 + 1.6 * foam_patches(in_world.xz)), 0.0, 1.0));
  out_color = finish_color(color);
}
