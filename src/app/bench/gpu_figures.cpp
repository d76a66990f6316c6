#include "app/bench/gpu_figures.h"

#include <chrono>
#include <optional>

#include "app/bench/cpu_figures.h"
#include "app/bench/frame_figures.h"
#include "app/bench/workloads.h"
#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/gpu_solver.h"
#include "render/pass_timestamps.h"
#include "sim/diagnostics.h"

namespace pond::bench {
namespace {

using Clock = std::chrono::steady_clock;

std::string device_type(vk::PhysicalDeviceType t) {
  switch (t) {
    case vk::PhysicalDeviceType::eDiscreteGpu: return "discrete GPU";
    case vk::PhysicalDeviceType::eIntegratedGpu: return "integrated GPU";
    case vk::PhysicalDeviceType::eVirtualGpu: return "virtual GPU";
    case vk::PhysicalDeviceType::eCpu: return "CPU";
    default: return "other";
  }
}

// The driver's version as its vendor encodes it (NVIDIA 10.8.8.6 bits; most others Vulkan's 10.10.12).
std::string driver_version(const gpu::Context& ctx, std::uint32_t v) {
  if (ctx.driver_id() == vk::DriverId::eNvidiaProprietary)
    return std::to_string(v >> 22) + "." + std::to_string((v >> 14) & 0xff) + "." + std::to_string((v >> 6) & 0xff);
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

Device describe(const gpu::Context& ctx) {
  const vk::PhysicalDeviceProperties p = ctx.physical().getProperties();
  const render::PassTimestamps probe(ctx, 0, {});
  const std::uint32_t api = ctx.api_version();
  return {.name = ctx.device_name(), .type = device_type(p.deviceType), .driver = ctx.driver(),
          .driver_version = driver_version(ctx, p.driverVersion),
          .api_version = std::to_string(VK_API_VERSION_MAJOR(api)) + "." + std::to_string(VK_API_VERSION_MINOR(api)) +
                         "." + std::to_string(VK_API_VERSION_PATCH(api)),
          .timestamps = probe.supported(), .no_timestamps = probe.unsupported_reason()};
}

void measure_gpu_solver(const gpu::Context& ctx, const Plan& plan, Progress& progress, Report& report) {
  for (const int size : plan.solver_sizes())
    for (const sim::MathMode math : {sim::MathMode::exact, sim::MathMode::fast}) {
      const char* math_name = math == sim::MathMode::exact ? "exact" : "fast";
      const std::string label = std::string(math_name) + " math, " + std::to_string(size) + "²";
      progress.show("GPU solver, " + label);
      gpu::GpuSolver solver(ctx, rippled_model(size, math));
      const std::int64_t steps = steps_per_sample(size, plan.node_steps_per_sample());
      solver.advance(kWarmSteps);
      solver.finish();
      Figure f = make_figure(std::string("gpu.") + math_name + "." + std::to_string(size), "GPU solver, " + label, "node-steps/s");
      for (int r = 0; r < plan.repeats(); ++r) {
        const auto t0 = Clock::now();
        solver.advance(steps);
        solver.finish();
        f.samples.push_back(double(size) * size * double(steps) / std::chrono::duration<double>(Clock::now() - t0).count());
      }
      f.hash = hex_hash(sim::state_hash(solver.read_state(), solver.model()));
      report.add(std::move(f));
    }
}

// The bodies' cost on the GPU solver, as measure_cpu_bodies has it on the CPU's: a step with 8 and
// 64 bodies over the same pond's without, alternated, each submission waited for.
void measure_gpu_bodies(const gpu::Context& ctx, const Plan& plan, Progress& progress, Report& report) {
  const int side = plan.bodies_grid();
  const std::int64_t steps = plan.quick ? 4 : 16;
  for (const int count : {8, 64}) {
    progress.show("bodies on the GPU solver, " + std::to_string(count) + " at " + std::to_string(side) + "²");
    gpu::GpuSolver plain(ctx, bodies_model(side, 0)), bodies(ctx, bodies_model(side, count));
    Figure f = make_figure("bodies.gpu." + std::to_string(count),
                           std::to_string(count) + " bodies, a step with / without, GPU solver, " + std::to_string(side) + "²",
                           "x", false);
    const auto run = [steps](gpu::GpuSolver& solver) {
      const auto t0 = Clock::now();
      solver.advance(steps);
      solver.finish();
      return std::chrono::duration<double>(Clock::now() - t0).count();
    };
    run(plain), run(bodies);
    for (int r = 0; r < plan.repeats() + 2; ++r) {
      double with = 0, without = 0;
      for (int k = 0; k < (plan.quick ? 2 : 4); ++k) without += run(plain), with += run(bodies);
      f.samples.push_back(with / without);
    }
    report.add(std::move(f));
  }
}

}  // namespace

void measure_gpu_groups(const Plan& plan, Progress& progress, Report& report) {
  if (!plan.runs("gpu") && !plan.runs("frame") && !plan.runs("bodies")) return;
  progress.show("opening the Vulkan device");
  gpu::ContextOptions options;
  options.device = plan.device;
  options.validation = plan.validation;
  std::optional<gpu::Context> opened;
  try {
    opened.emplace(options);
  } catch (const RuntimeError& e) {  // no Vulkan, no device: the CPU's figures still stand
    if (!plan.only.empty()) throw;     // unless the GPU's were asked for by name
    report.notes.push_back(std::string("the GPU's figures skipped: ") + e.what());
    return;
  }
  const gpu::Context& ctx = *opened;
  report.device = describe(ctx);
  if (plan.runs("gpu")) measure_gpu_solver(ctx, plan, progress, report);
  if (plan.runs("frame")) measure_frame(ctx, plan, progress, report);
  if (plan.runs("bodies")) measure_gpu_bodies(ctx, plan, progress, report);
  if (plan.validation && !ctx.validation_log().messages().empty())
    throw RuntimeError(std::to_string(ctx.validation_log().messages().size()) +
                       " Vulkan validation message(s), the first: " + ctx.validation_log().messages().front());
}

}  // namespace pond::bench
