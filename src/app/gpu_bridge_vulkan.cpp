// `pond simulate --solver gpu`: the GPU solver behind the one door the CPU-only command code knows
// (and the Vulkan headers' version for `pond --version`).
#include <cstdint>
#include <memory>
#include <string>

#include <vulkan/vulkan_core.h>

#include "app/gpu_bridge.h"
#include "gpu/context.h"
#include "gpu/gpu_solver.h"
#include "gpu/headless.h"

namespace pond::app {
namespace {

// A GpuSolver together with the context it runs on (a headless run has no other owner for it).
class HeadlessGpuSolver final : public sim::Solver {
 public:
  HeadlessGpuSolver(std::shared_ptr<const gpu::Context> ctx, const sim::WaterModel& model)
      : ctx_(std::move(ctx)), solver_(*ctx_, model) {}
  const sim::WaterModel& model() const override { return solver_.model(); }
  std::int64_t steps_done() const override { return solver_.steps_done(); }
  void advance(std::int64_t steps) override { solver_.advance(steps); }
  void perturb(const sim::PerturbationTable& table) override { solver_.perturb(table); }
  sim::WaterState read_state() override { return solver_.read_state(); }
  sim::HostDisplacements displacements() override { return solver_.displacements(); }
  void set_state(const sim::WaterState& state, std::int64_t steps) override { solver_.set_state(state, steps); }
  std::vector<sim::BodyState> read_bodies() override { return solver_.read_bodies(); }
  const sim::HostSnapshot* host_snapshot() override { return solver_.host_snapshot(); }
  void set_body_models(std::vector<sim::BodyModel> bodies) override { solver_.set_body_models(std::move(bodies)); }
  std::string engine() const override { return solver_.engine(); }
  std::string identity() const override { return solver_.identity(); }

 private:
  std::shared_ptr<const gpu::Context> ctx_;  // declared first: outlives the solver
  gpu::GpuSolver solver_;
};

}  // namespace

sim::GpuSolverFactory headless_gpu_solvers(const GpuRunOptions& options) {
  return [options, ctx = std::shared_ptr<const gpu::Context>()](const sim::WaterModel& model) mutable
             -> std::unique_ptr<sim::Solver> {
    if (!ctx) ctx = std::make_shared<const gpu::Context>(gpu::headless_options(options.device, options.validation));
    return std::make_unique<HeadlessGpuSolver>(ctx, model);
  };
}

std::string vulkan_in_build() {
  constexpr std::uint32_t v = VK_HEADER_VERSION_COMPLETE;
  return "Vulkan headers " + std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
         "." + std::to_string(VK_API_VERSION_PATCH(v));
}

}  // namespace pond::app
