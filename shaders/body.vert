#version 460
// The bodies (render/body_drawable.h): the unit sphere placed at each body's centre (its state,
// grid units, times the spacing) and scaled by its radius. The frame's constants go on to body.frag as flat varyings.
// POND_BODY_MIRROR (body_mirror.vert): mirrored about the water's rest plane y = 0 for the planar
// reflection (render/reflection_pass.h), lit as seen from the mirrored eye.
#extension GL_GOOGLE_include_directive : require

#include "shared/body_render.h"

layout(push_constant) uniform Frame { BodyFrame f; };

layout(location = kBodyAttribPoint) in vec4 in_point;
layout(location = kBodyAttribSize) in vec4 in_size;
layout(location = kBodyAttribAlbedo) in vec4 in_albedo;
layout(location = kBodyAttribCentre) in vec3 in_centre;

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = kBodyFlatEye) flat out vec4 out_eye;  // w: the radius (world)
layout(location = kBodyFlatSun) flat out vec3 out_sun;
layout(location = kBodyFlatSky) flat out vec3 out_sky;
layout(location = kBodyFlatAlbedo) flat out vec4 out_albedo;

void main() {
  out_world = in_centre * in_size.y + in_point.xyz * in_size.x;
  out_normal = in_point.xyz;
#ifdef POND_BODY_MIRROR
  out_eye = vec4(f.eye.x, -f.eye.y, f.eye.z, in_size.x);
  gl_Position = f.view_proj * vec4(out_world.x, -out_world.y, out_world.z, 1.0);
#else
  out_eye = vec4(f.eye.xyz, in_size.x);
  gl_Position = f.view_proj * vec4(out_world, 1.0);
#endif
  out_sun = f.sun.xyz;
  out_sky = f.sky.rgb;
  out_albedo = in_albedo;
}
