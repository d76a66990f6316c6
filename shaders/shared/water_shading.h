// GLSL helpers shared by the water and land shaders (GLSL only; kept under shared/ so that
// cmake/Shaders.cmake rebuilds every shader when it changes).

// The sky's colour at the horizon, from the zenith's.
vec3 sky_horizon(vec3 zenith) { return mix(zenith, vec3(1.0), 0.55); }

// The sun's disc: 1 inside its angular radius (about 1.2 degrees, larger than the real 0.27 so a
// pixel or two wide in the water's reflection), a soft edge, 0 outside; no exp/log per pixel.
float sun_disc(vec3 d, vec3 sun) { return smoothstep(0.99972, 0.99980, dot(d, sun)); }

// The sky in direction `d`: lighter towards the horizon, a glow around the sun and its disc; below
// the horizon (the far ground's haze, seen past the land's end) it darkens a little.
vec3 sky_color(vec3 zenith, vec3 horizon, vec3 d, vec3 sun) {
  const float up = clamp(d.y, 0.0, 1.0);
  vec3 base = mix(horizon, zenith, sqrt(up));
  base *= 1.0 - 0.25 * clamp(-d.y * 4.0, 0.0, 1.0);
  const float s = max(dot(d, sun), 0.0);
  float glow = s;  // ^256 by squaring (no exp/log per pixel)
  for (int k = 0; k < 8; ++k) glow *= glow;
  return base + glow * vec3(1.0, 0.9, 0.7) * 0.3 + sun_disc(d, sun) * vec3(6.0, 5.6, 4.8);
}

// True when the target is UNORM (POND_SPEC_ENCODE_SRGB, shared/water_render.h): the shader
// encodes sRGB itself. A constant, so an sRGB target's pipelines contain no encoding at all.
layout(constant_id = POND_SPEC_ENCODE_SRGB) const bool kEncodeSrgb = false;

// Linear colour in 0..1 -> what the target stores. For a UNORM target, the sRGB curve
// 1.055 c^(1/2.4) - 0.055 (12.92 c below 0.0031308) as a quartic in sqrt(c), fitted minimax on
// [0.0031308, 1]: within 0.2 of an 8-bit level of the exact curve, as close as llvmpipe's own
// encoding on an sRGB store (0.17), and a sqrt and four multiply-adds instead of pow's exp and log.
// (pond draws into UNORM targets: on llvmpipe the format's encoding on store costs more,
// render/color_format.h.)
vec3 encode_target(vec3 c) {
  if (kEncodeSrgb) {
    const vec3 lo = c * 12.92;
    const vec3 t = sqrt(c);
    const vec3 hi = -0.0369580108 + t * (1.44726325 + t * (-0.942558393 + t * (0.839809749 + t * -0.308320079)));
    c = mix(hi, lo, lessThanEqual(c, vec3(0.0031308)));
  }
  return c;
}

// Linear colour -> the target: tone-clamped, then encoded.
vec4 finish_color(vec3 c) {
  c = c / (vec3(1.0) + max(c - vec3(0.8), vec3(0.0)));  // soft shoulder above 0.8
  return vec4(encode_target(clamp(c, 0.0, 1.0)), 1.0);
}
