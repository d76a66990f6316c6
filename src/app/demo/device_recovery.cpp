// The demo when its device fails (demo_app_impl.h): a lost device (a driver reset, a hang, an
// unplugged GPU) or memory that cannot be allocated. Nothing of the pond is lost: the session goes
// on on the CPU from its journal (sim/session.h), the device and everything on it are made again,
// and the GPU solver comes back with the state carried over. Memory that ran short turns the
// effects off first, so the frame needs less of it; the panel says what happened.
#include <cstdio>

#include "app/demo/demo_app_impl.h"
#include "gpu/gpu_failure.h"
#include "sim/backends.h"

namespace pond::app::demo {
namespace {

// Devices made again without a good frame between them, before the demo gives up.
constexpr int kMaxRecoveries = 3;

}  // namespace

std::unique_ptr<GpuStack> make_gpu_stack(const DemoOptions& options, const Window& window, bool vsync,
                                         const FirstExtent& extent) {
  const std::string device = options.device.empty() ? std::string("(default)") : options.device;
  const auto make = [&] {
    return gpu::guard_gpu(device, "while setting up the window's device",
                          [&] { return std::make_unique<GpuStack>(options, window, vsync, extent); });
  };
  try {
    return make();
  } catch (const GpuFailure& failure) {  // memory may be free again once a half-made stack is gone
    if (failure.kind != GpuFailure::Kind::out_of_memory) throw;
    std::fprintf(stderr, "pond demo: %s; trying once more\n", failure.what());
    return make();
  }
}

void DemoApp::recover(const GpuFailure& first) {
  const bool was_gpu = session_->choice().gpu;
  session_->recover(first);  // on the CPU from the GPU solver's last copy and the journal; says so
  GpuFailure failure = first;
  bool said = was_gpu;  // the session said what happened
  for (;;) {
    if (++recoveries_ > kMaxRecoveries)
      throw RuntimeError(std::string(failure.what()) + ", " + std::to_string(kMaxRecoveries) +
                         " times without a frame drawn between: giving up");
    std::string what = said ? std::string("making the device again") : std::string(failure.what()) + "; making the device again";
    if (failure.kind == GpuFailure::Kind::out_of_memory) {
      settings_.effects = view::Effects::none();
      what += " with the effects off, so the frame needs less memory";
    }
    notice(what);
    if (tree_) base_scene_.tree = tree_->spec();
    bodies_.reset();
    tree_.reset();
    loop_.reset();
    if (gpu_) earlier_validation_messages_ += gpu_->ctx.validation_log().count();
    gpu_.reset();
    try {
      gpu_ = make_gpu_stack(options_, window_, settings_.vsync,
                            [this](const gpu::Context&) { return window_.framebuffer_extent(); });
      stats_.device = gpu_->ctx.device_name();
      session_->set_gpu_factory(gpu_->solvers.factory());
      gpu::guard_gpu(gpu_->ctx, "while setting up the frame", [&] { build_loop(); });
      break;
    } catch (const GpuFailure& again) {  // the new device failed too: once more, from the top
      failure = again;
      said = false;
    }
  }
  if (was_gpu) session_->set_solver(sim::SolverChoice{.gpu = true, .math = session_->choice().math});
  settings_.gpu_solver = session_->choice().gpu;
  stats_.solver = solver_label(session_->choice());
  notice("the device '" + gpu_->ctx.device_name() + "' is back; the water is on the " + stats_.solver +
         " at step " + std::to_string(session_->steps_done()));
}

}  // namespace pond::app::demo
