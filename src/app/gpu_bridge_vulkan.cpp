// `pond simulate --solver gpu`: the GPU solver behind the one door the CPU-only command code knows.
#include <algorithm>
#include <cmath>
#include <string>

#include "app/gpu_bridge.h"
#include "app/interrupt.h"
#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/headless.h"
#include "gpu/gpu_solver.h"

namespace pond::app {

sim::WaterState simulate_on_gpu(const sim::WaterModel& model, std::int64_t steps, const GpuRunOptions& options) {
  const gpu::Context ctx(gpu::headless_options(options.device, options.validation));
  gpu::GpuSolver solver(ctx, model);
  // In chunks, so that SIGINT/SIGTERM (app/interrupt.h) stop the run within a chunk's time.
  constexpr std::int64_t kChunk = 256;
  for (std::int64_t done = 0; done < steps;) {
    const std::int64_t n = std::min(kChunk, steps - done);
    solver.advance(n);
    done += n;
    throw_if_interrupted("after step " + std::to_string(done) + " of " + std::to_string(steps));
  }
  sim::WaterState state = solver.read_state();
  // The CPU solver refuses a run that blows up at the step it happens; the GPU does not stop to
  // check, so it refuses it at the end.
  for (std::size_t n = 0; n < state.nodes(); ++n)
    if (!std::isfinite(state.vx[n]) || !std::isfinite(state.vy[n]) || !std::isfinite(state.vz[n]))
      throw InputError("the water blew up on the GPU (non-finite velocity at node row " +
                       std::to_string(n / static_cast<std::size_t>(model.cols)) + ", col " +
                       std::to_string(n % static_cast<std::size_t>(model.cols)) +
                       "); lower physics.dt, raise physics.substeps or soften the perturbations");
  return state;
}

}  // namespace pond::app
