#include "gpu/float_policy.h"

namespace pond::gpu {

Identity exact_identity(const Context& ctx) {
  if (ctx.denorm_preserve() && ctx.signed_zero_preserve()) return Identity::guaranteed;
  // llvmpipe runs shaders with the host CPU's default floating-point state (tests/gpu/
  // test_float_policy.cpp pins that it keeps denormals and signed zeros).
  if (ctx.driver_id() == vk::DriverId::eMesaLlvmpipe && ctx.signed_zero_preserve()) return Identity::observed;
  return Identity::unknown;
}

std::string identity_line(const Context& ctx) {
  switch (exact_identity(ctx)) {
    case Identity::guaranteed:
      return "bit-identity with the CPU: guaranteed by the device's float controls (DenormPreserve and "
             "SignedZeroInfNanPreserve declared for 32-bit floats)";
    case Identity::observed:
      return "bit-identity with the CPU: observed, not guaranteed (" + ctx.device_name() +
             " does not advertise shaderDenormPreserveFloat32 but keeps denormals, as pond's parity tests check)";
    case Identity::unknown: break;
  }
  return "bit-identity with the CPU: not guaranteed (" + ctx.device_name() + " does not advertise " +
         (ctx.denorm_preserve() ? "shaderSignedZeroInfNanPreserveFloat32" : "shaderDenormPreserveFloat32") +
         "); `pond check` tells whether it gives the CPU's bits";
}

}  // namespace pond::gpu
