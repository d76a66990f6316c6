#pragma once
// A simulation session and the frame loop drawing it, set up as `pond render` does (GPU solvers on
// the test's context). Declared in that order: the loop lets go of the session first.
#include "gpu/gpu_solver.h"
#include "render/frame_loop.h"
#include "sim/session.h"

namespace pond::test {

struct DrawnSession {
  DrawnSession(const gpu::Context& ctx, const scene::Scene& scene, sim::SolverChoice solver, vk::Format format)
      : session(scene, solver, gpu::gpu_solver_factory(ctx)), loop(ctx, session, format) {}
  sim::Session session;
  render::FrameLoop loop;
};

}  // namespace pond::test
