#pragma once
// The GPU solvers a simulation session makes (through factory()) on one context, and the one it
// holds now: how the renderer finds the GPU solver's buffers to draw from without casting the
// session's solver. The context must outlive this, and this the session.
#include <memory>

#include "gpu/context.h"
#include "gpu/gpu_solver.h"
#include "sim/solver.h"

namespace pond::gpu {

class GpuSolvers {
 public:
  explicit GpuSolvers(const Context& ctx) : ctx_(ctx) {}
  GpuSolvers(const GpuSolvers&) = delete;
  GpuSolvers& operator=(const GpuSolvers&) = delete;

  // Makes GpuSolvers for a session (sim/session.h) whose every submission publishes the state for
  // the renderer, remembering the last one made while it lives.
  sim::GpuSolverFactory factory();
  // The GPU solver made last, if it still lives (the session holds it, or a CPU solver replaced it).
  const GpuSolver* live() const { return live_; }

 private:
  class Tracked;
  const Context& ctx_;
  const GpuSolver* live_ = nullptr;
};

// GpuSolvers on `ctx` for a session that nothing draws (pond simulate's, tests').
sim::GpuSolverFactory gpu_solver_factory(const Context& ctx);

}  // namespace pond::gpu
