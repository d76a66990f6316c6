#version 460
// The land's light comes from land.vert (per vertex, exact on its flat faces); here only the tone
// curve and the target's encoding, which are not linear and so stay per pixel.
#extension GL_GOOGLE_include_directive : require

#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(location = 0) in vec3 in_color;
layout(location = 0) out vec4 out_color;

void main() { out_color = finish_color(in_color); }
