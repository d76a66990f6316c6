// pond simulate: runs the water model headless and writes the contract's STATE.npy; with
// --checkpoint it saves the run (scene/checkpoint.h) on the way, at the end and when interrupted,
// and --resume goes on from such a file with the bits of a run that never stopped.
#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <functional>
#include <unistd.h>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/gpu_bridge.h"
#include "core/interrupt.h"
#include "core/errors.h"
#include "core/npy.h"
#include "core/output_file.h"
#include "core/output_paths.h"
#include "core/text.h"
#include "scene/checkpoint.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "sim/diagnostics.h"
#include "sim/session.h"

namespace pond::app {
namespace {

struct SimulateOptions {
  std::string scene, out, bodies_out, solver = "auto", math = "exact", device, checkpoint, resume;
  std::int64_t steps = -1, checkpoint_every = 0;
  int threads = 0;
};

// Advances the session by `steps`, drawing a progress bar on a terminal once the run passes one
// second, and stops between chunks when SIGINT or SIGTERM arrived (core/interrupt.h). With `every`
// > 0, calls `at_boundary` whenever the session's step count reaches a multiple of it. The chunks
// double from one step up to kChunkNodeSteps node-steps, whatever the timing, so a run makes the
// same calls every time (and a GPU the same submissions: tests/faults fails each of them).
constexpr double kChunkNodeSteps = 1 << 24;

void advance_with_progress(sim::Session& session, std::int64_t steps, std::int64_t every,
                           const std::function<void()>& at_boundary) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const bool tty = ::isatty(2);
  const sim::WaterModel& m = session.model();
  const auto largest = std::max<std::int64_t>(
      1, static_cast<std::int64_t>(kChunkNodeSteps / (static_cast<double>(m.nodes()) * m.substeps)));
  std::int64_t done = 0, chunk = 1;
  bool drawn = false;
  while (done < steps) {
    std::int64_t n = std::min(chunk, steps - done);
    if (every > 0) n = std::min(n, every - session.steps_done() % every);  // stop on the boundary
    session.advance(n);
    done += n;
    chunk = std::min(2 * chunk, largest);
    if (every > 0 && session.steps_done() % every == 0) at_boundary();
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

// --out, --bodies-out and --checkpoint: each writable, no two naming one file (--resume may be the
// --checkpoint: a run that saves over the file it came from).
void check_outputs(const SimulateOptions& o) {
  check_output_path(o.out);
  const std::pair<const std::string*, const char*> others[] = {{&o.bodies_out, "--bodies-out"},
                                                               {&o.checkpoint, "--checkpoint"}};
  for (const auto& [path, flag] : others) {
    if (path->empty()) continue;
    try {
      check_output_path(*path);
    } catch (const InputError& e) {
      throw InputError(std::string(flag) + ": " + e.what());
    }
  }
  check_distinct_outputs({{"--out", o.out}, {"--bodies-out", o.bodies_out}, {"--checkpoint", o.checkpoint}});
  // --checkpoint may be --resume's file: the run saves over the checkpoint it went on from.
  check_outputs_spare_inputs({{"--out", o.out}, {"--bodies-out", o.bodies_out}}, {{"--scene", o.scene}, {"--resume", o.resume}});
  check_outputs_spare_inputs({{"--checkpoint", o.checkpoint}}, {{"--scene", o.scene}});
  if (o.checkpoint_every > 0 && o.checkpoint.empty()) throw InputError("--checkpoint-every needs --checkpoint FILE");
  if (!o.resume.empty() && !o.scene.empty())
    throw InputError("--scene cannot be given with --resume: the scene is in the checkpoint");
}

int run_simulate(const SimulateOptions& o) {
  const sim::MathMode math = o.math == "fast" ? sim::MathMode::fast : sim::MathMode::exact;
  check_outputs(o);
  const InterruptScope interrupt_scope;  // SIGINT/SIGTERM stop the run (a checkpoint saves it first)
  auto notify = [](const std::string& text) { std::fprintf(stderr, "pond simulate: %s\n", text.c_str()); };
  const sim::SolverChoice choice = parse_solver(o.solver, math, o.threads);
  const sim::GpuSolverFactory gpu = headless_gpu_solvers(GpuRunOptions{o.device, false});
  scene::Scene scene;
  std::unique_ptr<sim::Session> session;
  if (!o.resume.empty()) {
    const scene::Checkpoint checkpoint = scene::read_checkpoint(o.resume);
    scene = checkpoint.scene;
    session = scene::resume_session(checkpoint, choice, gpu, notify);
  } else {
    scene = scene::load_scene(o.scene);
    sim::SessionSpec spec = scene::session_spec(scene);
    spec.notify = notify;
    session = std::make_unique<sim::Session>(std::move(spec), choice, gpu);
  }
  const std::int64_t first = session->steps_done(), last = first + o.steps;
  auto save = [&] {
    if (o.checkpoint.empty()) return;
    scene::write_checkpoint(o.checkpoint, scene, *session, session->image());
  };

  const auto t0 = std::chrono::steady_clock::now();
  try {
    advance_with_progress(*session, o.steps, o.checkpoint_every, save);
  } catch (const Interrupted& e) {
    if (o.checkpoint.empty()) throw;
    hold_interrupts();  // the checkpoint is written whole, whatever signal comes next
    save();
    const std::int64_t at = session->steps_done();
    throw Interrupted(e.signal, std::string("interrupted by ") + signal_name(e.signal) + " at step " +
                                    std::to_string(at) + " of " + std::to_string(last) + "; wrote " + escaped(o.checkpoint) +
                                    " (step " + std::to_string(at) + "); go on with: pond simulate --resume " +
                                    escaped(o.checkpoint) + " --steps " + std::to_string(last - at) + " --out " + escaped(o.out));
  }
  const sim::WaterState state = session->finite_state();
  if (const std::string clamped = session->clamp_notice(state.bodies); !clamped.empty())
    std::fprintf(stderr, "pond simulate: %s\n", clamped.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const sim::WaterModel& model = session->model();
  const std::string engine = session->solver().engine();

  throw_if_interrupted("after the last step");
  save();
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
  if (!o.resume.empty())
    std::printf("resumed at step %" PRId64 " from %s, now at step %" PRId64 "\n", first, escaped(o.resume).c_str(), last);
  std::printf("time %.3f s, %.1f M node-steps/s\n", seconds,
              seconds > 0 ? node_steps / seconds * 1e-6 : 0.0);
  std::printf("energy %.6g (kinetic %.6g, spring %.6g), max displacement %.6g\n", d.total(),
              d.kinetic, d.spring, d.max_displacement);
  std::printf("state hash %016" PRIx64 "\n", sim::state_hash(world));
  if (const std::string identity = session->solver().identity(); !identity.empty()) std::printf("%s\n", identity.c_str());
  if (!o.checkpoint.empty()) std::printf("wrote %s (checkpoint at step %" PRId64 ")\n", escaped(o.checkpoint).c_str(), last);
  std::printf("wrote %s\n", escaped(o.out).c_str());
  if (!o.bodies_out.empty()) std::printf("wrote %s (%zu bodies)\n", escaped(o.bodies_out).c_str(), state.bodies.size());
  return 0;
}

}  // namespace

Command add_simulate_command(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* sub = app.add_subcommand("simulate", "Run the water model headless and write STATE.npy");
  sub->add_option("--scene", o->scene, "Scene JSON file (default: the embedded scene)");
  sub->add_option("--steps", o->steps, "Number of time steps (with --resume: more steps)")
      ->required()
      ->transform(whole_number(0, std::int64_t{1} << 40));
  sub->add_option("--solver", o->solver, "Solver backend (default: the widest the CPU has)")
      ->check(CLI::IsMember({"auto", "scalar", "sse", "avx2", "avx512", "neon", "gpu"}));
  sub->add_option("--math", o->math, "Float math: exact (bit-reproducible, the default) or fast (approximations allowed)")
      ->check(CLI::IsMember({"exact", "fast"}));
  sub->add_option("--threads", o->threads, "CPU threads (default: all cores)")
      ->transform(whole_number(1, 1024));
  sub->add_option("--device", o->device, "Vulkan device name (substring) for --solver gpu");
  sub->add_option("--out", o->out, "Output STATE.npy: float32 (rows, cols, 6)")->required();
  sub->add_option("--bodies-out", o->bodies_out,
                  "Output BODIES.npy: float32 (bodies, 6) = x, y, z, vx, vy, vz after the last step");
  sub->add_option("--checkpoint", o->checkpoint,
                  "Save the run to FILE at the end, when interrupted, and with --checkpoint-every on the way");
  sub->add_option("--checkpoint-every", o->checkpoint_every, "Save the checkpoint every N steps too")
      ->transform(whole_number(1, std::int64_t{1} << 40));
  sub->add_option("--resume", o->resume, "Go on from a checkpoint FILE for --steps more steps (its scene: no --scene)");
  return {sub, [o] { return run_simulate(*o); }};
}

}  // namespace pond::app
