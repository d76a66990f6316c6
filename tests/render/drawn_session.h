#pragma once
// A simulation session and the frame loop drawing it, set up as `pond render` does (GPU solvers on
// the test's context, made by the GpuSolvers the loop finds them through). Declared in that order:
// the loop lets go of the session first.
#include "gpu/gpu_solvers.h"
#include "render/frame_loop.h"
#include "scene/session_spec.h"
#include "sim/session.h"

namespace pond::test {

struct DrawnSession {
  DrawnSession(const gpu::Context& ctx, const scene::Scene& scene, sim::SolverChoice solver, vk::Format format)
      : solvers(ctx), session(scene::session_spec(scene), solver, solvers.factory()),
        loop(ctx, scene, session, &solvers, format) {}
  gpu::GpuSolvers solvers;
  sim::Session session;
  render::FrameLoop loop;
};

}  // namespace pond::test
