#include "gpu/gpu_solvers.h"

namespace pond::gpu {

// A GpuSolver that tells its GpuSolvers when it goes.
class GpuSolvers::Tracked final : public GpuSolver {
 public:
  Tracked(GpuSolvers& owner, const sim::WaterModel& model) : GpuSolver(owner.ctx_, model, true), owner_(owner) {}
  ~Tracked() override {
    if (owner_.live_ == this) owner_.live_ = nullptr;
  }

 private:
  GpuSolvers& owner_;
};

sim::GpuSolverFactory GpuSolvers::factory() {
  return [this](const sim::WaterModel& model) -> std::unique_ptr<sim::Solver> {
    auto solver = std::make_unique<Tracked>(*this, model);
    live_ = solver.get();
    return solver;
  };
}

sim::GpuSolverFactory gpu_solver_factory(const Context& ctx) {
  return [&ctx](const sim::WaterModel& model) { return std::make_unique<GpuSolver>(ctx, model); };
}

}  // namespace pond::gpu
