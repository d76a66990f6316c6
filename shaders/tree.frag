#version 460
// Wind tree shading: the line look unlit (the article's), bark and leaves with the water's sun and
// sky (diffuse + sky ambient, the land's model), leaves lit from whichever side faces the camera
// and varied in shade per leaf so the crown is not one flat green, and the level of detail's twig
// lines (below).
//
// One source, one fragment shader per pipeline (cmake variants: POND_TREE_FRAG_LINE, _TWIG, _LEAF;
// none = bark): llvmpipe runs both sides of a branch under a mask, so a shader holding every
// material would make each tree pixel pay for all of them (the twig's acos and sin included).
#extension GL_GOOGLE_include_directive : require

#include "shared/tree_render.h"
#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in uvec2 in_material;  // material, shade variation
layout(location = 3) in float in_width_px;
layout(location = 4) noperspective in vec2 in_axis;
// The frame's constants (tree.vert; not the uniform block, see kTreeFlatEye in tree_render.h).
layout(location = kTreeFlatEye) flat in vec3 in_eye;
layout(location = kTreeFlatSun) flat in vec3 in_sun;
layout(location = kTreeFlatSky) flat in vec3 in_sky;
layout(location = kTreeFlatAlbedo) flat in vec3 in_albedo;  // this material's colour
layout(location = 0) out vec4 out_color;

const float kPi = 3.14159265;
const vec3 kSunColor = vec3(1.0, 0.96, 0.9);

// A twig line stands for a tube narrower than a pixel or so (tree/tree_lod.h), and lights the
// pixels that tube would: those whose centres lie within half its width of its axis (so a tube
// well under a pixel wide shows as the same broken dashes). The line's fragments interpolate a
// point of the axis (in window pixels), whose derivatives run along it: the distance across is the
// fragment centre's offset from that point along the axis's normal. Its colour is the tube's light
// averaged across its visible half as the eye sees it (weighted by projected width). Across the
// axis, with the sun and the eye phi apart, that mean of max(n.sun, 0) is
//     |sun across| ((pi - phi) cos(phi) + sin(phi)) / 4      (pi / 4 facing the sun, 0 against it),
// and the mean normal, for the sky's ambient, is pi / 4 times the unit eye direction across.
bool twig_covers_pixel(vec2 along_x, vec2 along_y) {
  const vec2 along = dot(along_x, along_x) >= dot(along_y, along_y) ? along_x : along_y;
  if (dot(along, along) < 1e-12) return true;  // a line seen end-on: a point
  const vec2 across = normalize(vec2(-along.y, along.x));
  return abs(dot(gl_FragCoord.xy - in_axis, across)) < 0.5 * in_width_px;
}

vec3 twig_color(vec3 axis) {
  const vec3 d = normalize(axis);
  const vec3 sun_across = in_sun - d * dot(in_sun, d);
  const vec3 eye = in_eye - in_world;
  const vec3 eye_across = eye - d * dot(eye, d);
  const float s = length(sun_across), e = length(eye_across);
  const float c = s > 1e-6 && e > 1e-6 ? clamp(dot(sun_across, eye_across) / (s * e), -1.0, 1.0) : 0.0;
  const float phi = acos(c);
  const float diffuse = s * ((kPi - phi) * c + sin(phi)) / 4.0;
  const float up = e > 1e-6 ? kPi / 4.0 * eye_across.y / e : 0.0;
  return in_albedo * (in_sky * (0.3 + 0.15 * up) + 0.85 * diffuse * kSunColor);
}

#if defined(POND_TREE_FRAG_LINE)
void main() { out_color = finish_color(in_albedo); }

#elif defined(POND_TREE_FRAG_TWIG)
void main() {
  if (!twig_covers_pixel(dFdx(in_axis), dFdy(in_axis))) discard;
  out_color = finish_color(twig_color(in_normal));
}

#elif defined(POND_TREE_FRAG_LEAF)
void main() {
  vec3 n = normalize(in_normal);
  if (dot(n, in_eye - in_world) < 0.0) n = -n;  // a leaf shows its lit side either way
  const float sun = dot(n, in_sun);
  const float shade = 0.75 + 0.5 * float(in_material.y) / 255.0;
  const vec3 ambient = in_sky * (0.3 + 0.15 * n.y);
  // Light through a leaf: its far side still glows a little when the sun is behind it.
  const float light = 0.85 * max(sun, 0.0) + 0.25 * max(-sun, 0.0);
  out_color = finish_color(in_albedo * shade * (ambient + light * kSunColor));
}

#else  // bark
void main() {
  const vec3 n = normalize(in_normal);
  const vec3 ambient = in_sky * (0.3 + 0.15 * n.y);
  out_color = finish_color(in_albedo * (ambient + 0.85 * max(dot(n, in_sun), 0.0) * kSunColor));
}
#endif
