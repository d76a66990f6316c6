#version 460
// A body's surface: the tree's and the land's light model (diffuse sun plus sky ambient brighter
// toward the zenith), with a small sun highlight, since the balls are smooth (painted plastic, not
// bark), and a rim of sky light at grazing angles. A held body (albedo.a = 1) is lightened, so the
// person dragging it sees which one it is. POND_BODY_MIRROR (body_mirror.frag): the reflection
// shows only what is above the water; POND_BODY_SUBMERGED (body_submerged.frag): the submerged
// layer (render/submerged_pass.h) only what is below it, with its view depths in and out.
#extension GL_GOOGLE_include_directive : require

#include "shared/body_render.h"
#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = kBodyFlatEye) flat in vec4 in_eye;  // w: the radius (world)
layout(location = kBodyFlatSun) flat in vec3 in_sun;
layout(location = kBodyFlatSky) flat in vec3 in_sky;
layout(location = kBodyFlatAlbedo) flat in vec4 in_albedo;
#ifdef POND_BODY_SUBMERGED
layout(location = 0) out uvec2 out_layer;  // render/submerged_pass.h
#else
layout(location = 0) out vec4 out_color;
#endif

const vec3 kSunColor = vec3(1.0, 0.96, 0.9);

void main() {
#ifdef POND_BODY_MIRROR
  if (in_world.y < 0.0) discard;  // (its mirror image is lit as the mirrored eye sees the body)
#endif
#ifdef POND_BODY_SUBMERGED
  if (in_world.y > 0.0) discard;
#endif
  const vec3 n = normalize(in_normal);
  const vec3 v = normalize(in_eye.xyz - in_world);
  const vec3 albedo = mix(in_albedo.rgb, vec3(1.0), 0.35 * in_albedo.a);
  const float diffuse = max(dot(n, in_sun), 0.0);
  const vec3 ambient = in_sky * (0.3 + 0.15 * n.y);
  // Blinn-Phong highlight, exponent 64 by squaring (no pow per pixel on llvmpipe).
  float spec = max(dot(n, normalize(in_sun + v)), 0.0);
  for (int k = 0; k < 6; ++k) spec *= spec;
  const float rim = 1.0 - max(dot(n, v), 0.0);
  const vec3 c = albedo * (ambient + 0.85 * diffuse * kSunColor) + 0.35 * spec * kSunColor +
                 0.15 * rim * rim * in_sky;
#ifdef POND_BODY_SUBMERGED
  // The view depth where the eye's line leaves the sphere: the chord from this entry point is
  // 2 r cos(angle to the normal), and view depth grows along the line as it does to here.
  const float front = 1.0 / gl_FragCoord.w, to_here = distance(in_eye.xyz, in_world);
  const float back = front + 2.0 * in_eye.w * max(dot(n, v), 0.0) * front / to_here;
  out_layer = uvec2(packUnorm4x8(finish_color(c)), packHalf2x16(vec2(front, back)));
#else
  out_color = finish_color(c);
#endif
}
