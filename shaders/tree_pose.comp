#version 460
// The parity test's shader (tests/render/test_tree_render.cpp): every skeleton vertex bent by
// shared/tree_pose.h, the code tree.vert runs, written out as three floats per vertex. The test
// compares the result with the CPU evaluation (src/tree/bend.cpp) bit for bit.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require

#include "shared/tree_render.h"
#include "shared/tree_pose.h"

spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve, 32-bit floats

layout(local_size_x = POND_TREE_POSE_LOCAL_X, local_size_y = 1, local_size_z = 1) in;
layout(std430, set = 0, binding = 3) restrict writeonly buffer Out { float bent[]; };
layout(push_constant) uniform Instance { TreeInstance inst; };

void main() {
  const uint v = gl_GlobalInvocationID.x;
  if (v >= uint(tree_parents.length())) return;
  const vec3 p = tree_pose(v, inst.wind);
  bent[3u * v] = p.x;
  bent[3u * v + 1u] = p.y;
  bent[3u * v + 2u] = p.z;
}
