#pragma once
// pond's policy for denormals and signed zeros in the exact GPU path (and why it is enough for
// the GPU to give the CPU's bits).
//
// Denormals: PRESERVED on both sides. The CPU is IEEE by default (no FTZ/DAZ in MXCSR; pond never
// sets them). On the GPU Vulkan leaves denormal handling to the implementation unless a shader
// declares DenormPreserve, which needs shaderDenormPreserveFloat32: the exact shaders declare it
// wherever the device advertises it (their _denorm variants), and there bit-identity is
// guaranteed. lavapipe does not advertise it, but llvmpipe's generated code runs with the host's
// default MXCSR and preserves denormals in fact, so there it is observed, not guaranteed. tests/gpu/test_float_policy.cpp pins that (denormal results, denormal operands, the exact
// rsqrt of a denormal) and the parity suite exercises it: the leading edge of every wave decays
// through the denormal range, so a flushing device fails parity within a few hundred steps. On a
// device that flushes, exact mode is still the exact algorithm but no longer bit-identical to the
// CPU; the suite says so at the first differing step and node.
//
// Signed zeros: PRESERVED and deliberate. Every water shader declares SignedZeroInfNanPreserve
// (shaderSignedZeroInfNanPreserveFloat32, which lavapipe supports), so the compiler may not fold
// x + 0.0 -> x or 0.0 * x -> 0.0; all arithmetic is `precise`. The per-node sum starts at -0.0
// (the identity of IEEE addition), constrained velocity components are written as +0.0 (not
// v * 0, which could be -0), and a spring evaluated from its far end is the exact negation of the
// CPU's (it is only ever the sign of a zero term that can differ, and no state bit depends on
// it: v' = v + (G*kc - v*kd) is +0 whenever G and v are zeros). The probe test pins the IEEE
// signed-zero rules of +, - and * on the device.
#include <string>

#include "gpu/context.h"

namespace pond::gpu {

// Whether the exact path needs the device to preserve denormals (documentation for callers).
inline constexpr bool kExactNeedsDenormPreserve = true;

// What the device's float controls promise about the exact path giving the CPU's bits.
enum class Identity {
  guaranteed,  // DenormPreserve and SignedZeroInfNanPreserve for 32-bit floats are declared
  observed,    // not promised, but this driver is known to keep denormals (llvmpipe)
  unknown,     // not promised: `pond check` tells
};
Identity exact_identity(const Context& ctx);
// One line saying which, and why, for `pond simulate --solver gpu --math exact` and `pond check`.
std::string identity_line(const Context& ctx);

}  // namespace pond::gpu
