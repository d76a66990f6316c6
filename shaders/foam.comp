#version 460
// Foam (shared/foam.h): one invocation per node reads the node's displacement and the one of the
// last update (which it then replaces) and the last foam around it, and writes this update's foam.
// Outside the physics: its output is drawn (water.vert), never read by the solver.
#extension GL_GOOGLE_include_directive : require

#include "shared/foam.h"

layout(local_size_x = POND_FOAM_LOCAL_X) in;

layout(std430, set = 0, binding = POND_FOAM_BINDING_STATE) restrict readonly buffer State { float state[]; };
layout(std430, set = 0, binding = POND_FOAM_BINDING_FROM) restrict readonly buffer From { float from_foam[]; };
layout(std430, set = 0, binding = POND_FOAM_BINDING_TO) restrict writeonly buffer To { float to_foam[]; };
layout(std430, set = 0, binding = POND_FOAM_BINDING_LAST) restrict buffer Last { vec4 last[]; };
layout(push_constant) uniform Push { FoamPush p; };

void main() {
  const uint rows = p.grid.x, cols = p.grid.y, stride = p.grid.z, pitch = p.grid.w;
  const uint col = gl_GlobalInvocationID.x, row = gl_GlobalInvocationID.y;  // one row a workgroup row
  if (col >= cols || row >= rows) return;
  const uint n = row * cols + col, m = row * pitch + col;
  const vec3 u = vec3(state[m], state[stride + m], state[2u * stride + m]);
  const float moved = length(u - last[n].xyz);
  last[n] = vec4(u, 0.0);
  const float stir = clamp((moved * p.update.w - kFoamStirLow) / (kFoamStirHigh - kFoamStirLow), 0.0, 1.0);
  // The four neighbours, the edge's own value past the edge.
  const float here = from_foam[n];
  const float left = col > 0u ? from_foam[n - 1u] : here, right = col + 1u < cols ? from_foam[n + 1u] : here;
  const float up = row > 0u ? from_foam[n - cols] : here, down = row + 1u < rows ? from_foam[n + cols] : here;
  const float spread = mix(here, 0.25 * (left + right + up + down), p.update.z);
  to_foam[n] = clamp(spread * p.update.x + p.update.y * stir, 0.0, 1.0);
}
