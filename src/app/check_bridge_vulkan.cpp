// `pond check`: the parity suite's lockstep comparison (gpu/parity_check.h) over the built-in
// cases, on the chosen device, as a table a user can read.
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <optional>
#include <string>

#include "app/check_bridge.h"
#include "app/check_cases.h"
#include "core/interrupt.h"
#include "app/version.h"
#include "gpu/context.h"
#include "gpu/float_policy.h"
#include "gpu/gpu_failure.h"
#include "gpu/headless.h"
#include "gpu/parity_check.h"
#include "scene/scene.h"
#include "sim/model.h"

namespace pond::app {
namespace {

const char* yes_no(vk::Bool32 b) { return b ? "true" : "false"; }

std::string version(std::uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

void print_device(const gpu::Context& ctx) {
  const auto props = ctx.physical().getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceVulkan12Properties>();
  const vk::PhysicalDeviceProperties& p = props.get<vk::PhysicalDeviceProperties2>().properties;
  const auto& v12 = props.get<vk::PhysicalDeviceVulkan12Properties>();
  std::printf("device: %s (%s), driver %s, driver version 0x%08x, Vulkan %s\n", ctx.device_name().c_str(),
              vk::to_string(p.deviceType).c_str(), ctx.driver().c_str(), p.driverVersion, version(p.apiVersion).c_str());
  std::printf("float controls, 32-bit: shaderDenormPreserveFloat32 %s, shaderDenormFlushToZeroFloat32 %s, "
              "shaderSignedZeroInfNanPreserveFloat32 %s, denormBehaviorIndependence %s\n",
              yes_no(v12.shaderDenormPreserveFloat32), yes_no(v12.shaderDenormFlushToZeroFloat32),
              yes_no(v12.shaderSignedZeroInfNanPreserveFloat32), vk::to_string(v12.denormBehaviorIndependence).c_str());
  std::printf("%s\n", gpu::identity_line(ctx).c_str());
}

// The cases on `ctx`, a table line each (a Vulkan failure reaches run_check).
int check_cases_on(const CheckOptions& o, const gpu::Context& ctx) {
  std::printf("%s\n", version_line().c_str());  // first, so a report that is passed on names its build
  std::printf("pond check: the GPU's exact math against the CPU reference, bit for bit, on %s\n\n",
              ctx.device_name().c_str());
  std::printf("%-26s %-7s %7s  %s\n", "case", "grid", "steps", "result");
  int differing = 0;
  for (const CheckCase& c : check_cases()) {
    const sim::WaterModel model = sim::build_model(check_scene(c));
    const std::int64_t steps = o.steps > 0 ? o.steps : c.steps;
    const std::string grid = std::to_string(model.rows) + "x" + std::to_string(model.cols);
    const std::optional<gpu::Difference> d = gpu::run_parity(ctx, model, steps, std::min<std::int64_t>(steps, 250), c.name);
    throw_if_interrupted(std::string("during case ") + c.name);
    std::printf("%-26s %-7s %7" PRId64 "  %s\n", c.name, grid.c_str(), steps, d ? "DIFFERS" : "identical");
    if (d) {
      ++differing;
      std::printf("    %s\n", gpu::describe(*d, model).c_str());
    }
    std::fflush(stdout);
  }
  std::printf("\n");
  print_device(ctx);
  const auto total = check_cases().size();
  if (differing == 0) {
    std::printf("all %zu cases bit-identical\n", total);
    return 0;
  }
  std::printf("%d of %zu cases differ from the CPU\n", differing, total);
  return 1;
}

}  // namespace

// A lost device or memory it cannot allocate ends the check with one line.
int run_check(const CheckOptions& o) {
  const InterruptScope interrupt_scope;
  const gpu::Context ctx(gpu::headless_options(o.device, false));
  return gpu::guard_gpu(ctx, "during pond check", [&] { return check_cases_on(o, ctx); });
}

}  // namespace pond::app
