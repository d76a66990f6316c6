#version 450
// Compile check of shaders/shared/tree_wind.h as GLSL (tests/tree/CMakeLists.txt): a vertex shader
// shaped like the future tree.vert, using the vertex layout, the uniform block and every function.
#extension GL_GOOGLE_include_directive : require
#include "shared/tree_wind.h"

layout(location = kTreeAttribPosition) in vec3 in_position;
layout(location = kTreeAttribWindX) in vec3 in_wind_x;
layout(location = kTreeAttribWindZ) in vec3 in_wind_z;
layout(location = kTreeAttribJitter) in vec3 in_jitter;
layout(std140, binding = 0) uniform Wind { TreeWindFrame frame; };

void main() {
  vec3 p = tree_wind_bend(in_position, in_wind_x, in_wind_z, in_jitter, frame.wind.x, frame.wind.z,
                          frame.twig.xyz);
  if (frame.bend_mode == kTreeBendKeepLength) {
    float rest = tree_wind_rest_length(vec3(0.0), in_position);
    p = tree_wind_keep_length(vec3(0.0), vec3(0.0), p, rest);
  }
  gl_Position = vec4(p, 1.0);
}
