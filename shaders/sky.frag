#version 460
// The sky seen past the land's end: the gradient, the sun's glow and disc of sky_color, the very
// function the water's reflection and Fresnel term use, so the sky and its mirror image agree.
#extension GL_GOOGLE_include_directive : require

#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(location = 0) in vec3 in_world;
layout(location = 1) flat in vec3 in_eye;
layout(location = 2) flat in vec3 in_sun;
layout(location = 3) flat in vec3 in_sky;
layout(location = 4) flat in vec3 in_horizon;
layout(location = 0) out vec4 out_color;

void main() { out_color = finish_color(sky_color(in_sky, in_horizon, normalize(in_world - in_eye), in_sun)); }
