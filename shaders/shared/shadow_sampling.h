// The sun's shadow (render/shadow_pass.h) as the land and the water receive it: GLSL only, included
// after shared/water_render.h (its binding and specialization constant). Kept under shared/ so that
// cmake/Shaders.cmake rebuilds every shader when it changes.

// On in the pipelines that sample the map (POND_SPEC_SHADOWS): off, sun_light() is the constant 1
// and the shaders hold no shadow code.
layout(constant_id = POND_SPEC_SHADOWS) const bool kShadows = false;
// Depth compare (less or equal: lit where the point is no deeper than the caster nearest the sun),
// nearest texels, border at the far depth (shadow_pass.h).
layout(set = 0, binding = POND_RENDER_BINDING_SHADOW) uniform sampler2DShadow shadow_map;

// How much of the sun reaches the point at `s` in the shadow map (WaterFrame::shadow applied to
// its world position): 1 in the sun, 0 in full shadow, between on the edge. The four texels around
// it are compared in one gather and blended bilinearly (a 2x2 percentage-closer filter, as the
// hardware's linear compare filter would, which not every device has for depth formats: lavapipe
// has not). A point off the map lies outside every caster's shadow: the border compares as lit. A
// point deeper than the casters' range compares at its far end, so it is shaded wherever a caster
// is above it.
float sun_light(vec3 s) {
  if (!kShadows) return 1.0;
  const vec2 size = vec2(textureSize(shadow_map, 0));
  const vec2 t = s.xy * size - 0.5;  // texel space, texel centres on integers
  const vec2 f = fract(t);
  // Gather's texels: w (i0, j0), z (i1, j0), x (i0, j1), y (i1, j1) around this coordinate.
  const vec4 lit = textureGather(shadow_map, (floor(t) + 1.0) / size, clamp(s.z, 0.0, 1.0));
  return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
}
