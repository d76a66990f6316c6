#version 460
// The float-policy probe (test_float_policy.cpp): one correctly rounded operation per case, under
// the same float controls and `precise` as the water shaders, so the test sees what the device
// does with denormals and signed zeros in exactly the solver's setting.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require

#include "shared/exact_math.h"

spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve, 32-bit floats

layout(local_size_x = 8) in;
layout(std430, set = 0, binding = 0) restrict readonly buffer In { vec2 operands[]; };
layout(std430, set = 0, binding = 1) restrict writeonly buffer Out { vec4 results[]; };
layout(push_constant) uniform Push { uint count; };

void main() {
  const uint k = gl_GlobalInvocationID.x;
  if (k >= count) return;
  const vec2 o = operands[k];
  precise float sum = o.x + o.y;
  precise float difference = o.x - o.y;
  precise float product = o.x * o.y;
  precise float rsqrt = rsqrt_exact(abs(o.x), kRsqrtStepsExact);
  results[k] = vec4(sum, difference, product, rsqrt);
}
