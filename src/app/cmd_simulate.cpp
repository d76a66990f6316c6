// pond simulate: runs the water model headless and writes the contract's STATE.npy.
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <unistd.h>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/gpu_bridge.h"
#include "app/interrupt.h"
#include "core/errors.h"
#include "core/npy.h"
#include "core/output_file.h"
#include "core/output_paths.h"
#include "core/text.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "sim/diagnostics.h"
#include "sim/session.h"

namespace pond::app {
namespace {

struct SimulateOptions {
  std::string scene, out, bodies_out, solver = "auto", math = "exact", device;
  std::int64_t steps = -1;
  int threads = 0;
};

// Advances the session, drawing a progress bar on a terminal once the run passes one second, and
// stops between chunks when SIGINT or SIGTERM arrived (app/interrupt.h).
void advance_with_progress(sim::Session& session, std::int64_t steps) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const bool tty = ::isatty(2);
  std::int64_t done = 0, chunk = 1;
  bool drawn = false;
  while (done < steps) {
    const std::int64_t n = std::min(chunk, steps - done);
    const auto t0 = clock::now();
    session.advance(n);
    done += n;
    const double chunk_s = std::chrono::duration<double>(clock::now() - t0).count();
    if (chunk_s < 0.05) chunk *= 2;  // keep checks about 20 per second
    if (g_interrupt_signal) {
      if (drawn) std::fprintf(stderr, "\r%*s\r", 80, "");
      throw_if_interrupted("after step " + std::to_string(done) + " of " + std::to_string(steps));
    }
    if (tty && std::chrono::duration<double>(clock::now() - start).count() > 1.0) {
      const int width = 40, filled = static_cast<int>(width * done / steps);
      std::fprintf(stderr, "\r[%.*s%*s] %3d%% step %" PRId64 "/%" PRId64, filled,
                   "########################################", width - filled, "",
                   static_cast<int>(100 * done / steps), done, steps);
      drawn = true;
    }
  }
  if (drawn) std::fprintf(stderr, "\r%*s\r", 80, "");
}

int run_simulate(const SimulateOptions& o) {
  const sim::MathMode math = o.math == "fast" ? sim::MathMode::fast : sim::MathMode::exact;
  check_output_path(o.out);
  if (!o.bodies_out.empty()) {
    try {
      check_output_path(o.bodies_out);
    } catch (const InputError& e) {
      throw InputError(std::string("--bodies-out: ") + e.what());
    }
    check_distinct_outputs({{"--out", o.out}, {"--bodies-out", o.bodies_out}});
  }
  const InterruptScope interrupt_scope;  // SIGINT/SIGTERM stop the run before anything is written
  sim::Session session(scene::session_spec(scene::load_scene(o.scene)), parse_solver(o.solver, math, o.threads),
                       headless_gpu_solvers(GpuRunOptions{o.device, false}));

  const auto t0 = std::chrono::steady_clock::now();
  advance_with_progress(session, o.steps);
  const sim::WaterState state = session.finite_state();
  if (const std::string clamped = session.clamp_notice(state.bodies); !clamped.empty())
    std::fprintf(stderr, "pond simulate: %s\n", clamped.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const sim::WaterModel& model = session.model();
  const std::string engine = session.solver().engine();

  throw_if_interrupted("after the last step");
  const std::vector<float> world = sim::to_world_interleaved(state, model);
  const std::size_t shape[3] = {static_cast<std::size_t>(model.rows),
                                static_cast<std::size_t>(model.cols), 6};
  write_npy(o.out, NpyType::f32, shape, std::as_bytes(std::span(world)));
  if (!o.bodies_out.empty()) {
    const std::vector<float> bodies = sim::bodies_to_world(state.bodies, model.spacing);
    const std::size_t bodies_shape[2] = {state.bodies.size(), 6};
    write_npy(o.bodies_out, NpyType::f32, bodies_shape, std::as_bytes(std::span(bodies)));
  }

  const sim::Diagnostics d = sim::diagnose(state, model);
  const double node_steps = static_cast<double>(model.nodes()) * model.substeps * static_cast<double>(o.steps);
  std::printf("simulated %" PRId64 " steps (%d substep%s each) of a %d x %d grid on %s, %s math\n",
              o.steps, model.substeps, model.substeps == 1 ? "" : "s", model.rows, model.cols,
              engine.c_str(), o.math.c_str());
  std::printf("time %.3f s, %.1f M node-steps/s\n", seconds,
              seconds > 0 ? node_steps / seconds * 1e-6 : 0.0);
  std::printf("energy %.6g (kinetic %.6g, spring %.6g), max displacement %.6g\n", d.total(),
              d.kinetic, d.spring, d.max_displacement);
  std::printf("state hash %016" PRIx64 "\n", sim::state_hash(world));
  if (const std::string identity = session.solver().identity(); !identity.empty()) std::printf("%s\n", identity.c_str());
  std::printf("wrote %s\n", escaped(o.out).c_str());
  if (!o.bodies_out.empty()) std::printf("wrote %s (%zu bodies)\n", escaped(o.bodies_out).c_str(), state.bodies.size());
  return 0;
}

}  // namespace

Command add_simulate_command(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* sub = app.add_subcommand("simulate", "Run the water model headless and write STATE.npy");
  sub->add_option("--scene", o->scene, "Scene JSON file (default: the embedded scene)");
  sub->add_option("--steps", o->steps, "Number of time steps")->required()->transform(whole_number(0, std::int64_t{1} << 40));
  sub->add_option("--solver", o->solver, "Solver backend (default: the widest the CPU has)")
      ->check(CLI::IsMember({"auto", "scalar", "sse", "avx2", "avx512", "gpu"}));
  sub->add_option("--math", o->math, "Float math: exact (bit-reproducible, the default) or fast (approximations allowed)")
      ->check(CLI::IsMember({"exact", "fast"}));
  sub->add_option("--threads", o->threads, "CPU threads (default: all cores)")
      ->transform(whole_number(1, 1024));
  sub->add_option("--device", o->device, "Vulkan device name (substring) for --solver gpu");
  sub->add_option("--out", o->out, "Output STATE.npy: float32 (rows, cols, 6)")->required();
  sub->add_option("--bodies-out", o->bodies_out,
                  "Output BODIES.npy: float32 (bodies, 6) = x, y, z, vx, vy, vz after the last step");
  return {sub, [o] { return run_simulate(*o); }};
}

}  // namespace pond::app
