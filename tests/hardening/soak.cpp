// pond_soak: the long run of issue 8. A 129 x 129 pond (the paper's physics, fixed border) gets a
// splash every 50 steps at a pseudo-random place, alternating up and down, and is advanced on the CPU
// solver and on the GPU solver side by side. At every checkpoint it checks that
//  - both states are finite (the CPU solver also refuses a blow-up at the step it happens),
//  - the CPU and the GPU states are the same bits (exact math: their hashes are equal),
//  - the energy stays bounded: after the warm-up (the first tenth of the run), never above
//    kEnergyFactor times the largest energy seen during the warm-up (the damping makes the pond
//    reach a steady state within a few hundred steps; drift or an instability grows without bound;
//    the first checkpoints count as warm-up until each of the GPU solver's ring of command buffers
//    has been recorded once: each keeps the driver's memory for the longest one),
// and at the end that memory did not grow since the end of the warm-up (lavapipe and the allocator
// settle during the first checkpoints, about 3 MB on Mesa 22.3):
//  - the heap in use (malloc's live bytes, every arena) by at most kHeapSlackKiB: a leak of even
//    one state-sized buffer a checkpoint fails it;
//  - the resident memory (VmRSS), read after malloc_trim(0), by at most kRssSlackKiB: leaks outside
//    malloc. Trimming first returns the freed pages the allocator kept, whose count depends on how
//    the driver's threads happened to interleave.
// Prints one line per checkpoint and a summary; exit 0 when every check held, 1 otherwise, 2 for a
// bad command line.
//
//   pond_soak [--steps N] [--splash-every K] [--size N] [--checkpoints C] [--cpu-only]
//             [--threads T] [--device NAME]
// scripts/soak.sh builds and runs it (default: 1,000,000 steps).

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <malloc.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/gpu_solver.h"
#include "gpu/headless.h"
#include "gpu/submission_ring.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"
#include "sim/model.h"
#include "scene/scene.h"

namespace {

constexpr double kEnergyFactor = 4.0;
constexpr long kRssSlackKiB = 4096;
constexpr long kHeapSlackKiB = 1024;

struct Options {
  std::int64_t steps = 1000000;
  std::int64_t splash_every = 50;
  int size = 129;
  std::int64_t checkpoints = 100;
  bool gpu = true;
  int threads = 0;
  std::string device;
};

long rss_kib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
  return -1;
}

// malloc's bytes in use, summed over its arenas (the driver's threads allocate in their own).
long heap_kib() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<long>((m.uordblks + m.hblkhd) / 1024);
}

// The splashes: a small xorshift so the sequence is the same on every machine.
pond::scene::Scene soak_scene(const Options& o) {
  pond::scene::Scene s;
  s.name = "soak";
  s.grid.rows = s.grid.cols = o.size;
  s.border = pond::sim::NodeKind::fixed;
  std::uint32_t x = 2463534242u;
  auto next = [&x] {
    x ^= x << 13, x ^= x >> 17, x ^= x << 5;
    return x;
  };
  const int margin = 4, span = o.size - 2 * margin;
  for (std::int64_t step = 0, k = 0; step < o.steps; step += o.splash_every, ++k) {
    pond::sim::Perturbation p;
    p.step = step;
    p.row = margin + static_cast<double>(next() % static_cast<std::uint32_t>(span));
    p.col = margin + static_cast<double>(next() % static_cast<std::uint32_t>(span));
    p.radius = 2.0;
    p.amplitude = k % 2 == 0 ? 0.5 : -0.5;
    s.perturbations.push_back(p);
  }
  return s;
}

bool finite(const pond::sim::WaterState& s) {
  for (const auto* a : {&s.ux, &s.uy, &s.uz, &s.vx, &s.vy, &s.vz})
    for (std::size_t n = 0; n < s.nodes(); ++n)
      if (!std::isfinite((*a)[n])) return false;
  return true;
}

bool parse_args(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](auto& out) {
      if (i + 1 >= argc) return false;
      char* end = nullptr;
      const long long v = std::strtoll(argv[++i], &end, 10);
      if (*end != '\0' || v < 1) return false;
      out = static_cast<std::remove_reference_t<decltype(out)>>(v);
      return true;
    };
    bool ok = true;
    if (a == "--steps") ok = value(o.steps);
    else if (a == "--splash-every") ok = value(o.splash_every);
    else if (a == "--size") ok = value(o.size) && o.size >= 16 && o.size <= 4096;
    else if (a == "--checkpoints") ok = value(o.checkpoints);
    else if (a == "--threads") ok = value(o.threads);
    else if (a == "--cpu-only") o.gpu = false;
    else if (a == "--device" && i + 1 < argc) o.device = argv[++i];
    else ok = false;
    if (!ok) {
      std::fprintf(stderr, "pond_soak: bad argument '%s'\nusage: pond_soak [--steps N] [--splash-every K] "
                           "[--size N (16..4096)] [--checkpoints C] [--cpu-only] [--threads T] [--device NAME]\n",
                   a.c_str());
      return false;
    }
  }
  o.checkpoints = std::min(o.checkpoints, o.steps);
  return true;
}

int run(const Options& o) {
  using clock = std::chrono::steady_clock;
  const pond::scene::Scene scene = soak_scene(o);
  const pond::sim::WaterModel model = pond::sim::build_model(scene, pond::sim::MathMode::exact);
  pond::sim::CpuSolver cpu(model, pond::sim::best_backend(), o.threads);
  std::optional<pond::gpu::Context> ctx;
  std::optional<pond::gpu::GpuSolver> gpu;
  if (o.gpu) {
    ctx.emplace(pond::gpu::headless_options(o.device, false));
    gpu.emplace(*ctx, model);
  }
  std::printf("soak: %" PRId64 " steps of a %d x %d pond, a splash every %" PRId64 " steps (%zu), CPU %s x %d%s%s\n",
              o.steps, o.size, o.size, o.splash_every, model.perturbations.size(),
              pond::sim::backend_name(cpu.backend()), cpu.threads(), o.gpu ? ", GPU " : "",
              o.gpu ? ctx->device_name().c_str() : "");
  std::fflush(stdout);

  const auto start = clock::now();
  double cpu_s = 0, gpu_s = 0;
  const std::int64_t warmup_end = std::max<std::int64_t>(o.steps / 10, 1);
  double warmup_max = 0, e_min = INFINITY, e_max = 0;
  long rss_first = -1, rss_warm = -1, rss_last = -1, heap_warm = -1, heap_last = -1;
  int failures = 0;
  std::int64_t done = 0;
  for (std::int64_t c = 1; c <= o.checkpoints; ++c) {
    const std::int64_t target = o.steps * c / o.checkpoints;
    auto t0 = clock::now();
    cpu.advance(target - done);
    cpu_s += std::chrono::duration<double>(clock::now() - t0).count();
    const std::uint64_t cpu_hash = pond::sim::state_hash(cpu.state(), model);
    std::uint64_t gpu_hash = cpu_hash;
    if (gpu) {
      t0 = clock::now();
      gpu->advance(target - done);
      const pond::sim::WaterState g = gpu->read_state();
      gpu_s += std::chrono::duration<double>(clock::now() - t0).count();
      if (!finite(g)) ++failures, std::printf("FAIL: the GPU state is not finite at step %" PRId64 "\n", target);
      gpu_hash = pond::sim::state_hash(g, model);
    }
    done = target;
    if (!finite(cpu.state())) ++failures, std::printf("FAIL: the CPU state is not finite at step %" PRId64 "\n", done);
    const double e = pond::sim::diagnose(cpu.state(), model).total();
    e_min = std::min(e_min, e), e_max = std::max(e_max, e);
    const bool warming = done <= warmup_end || c <= pond::gpu::SubmissionRing::kSize;
    if (warming) warmup_max = std::max(warmup_max, e);
    else if (!(e <= kEnergyFactor * warmup_max))
      ++failures, std::printf("FAIL: energy %.6g at step %" PRId64 " is above %g x the warm-up's largest %.6g\n",
                              e, done, kEnergyFactor, warmup_max);
    if (gpu_hash != cpu_hash)
      ++failures, std::printf("FAIL: CPU %016" PRIx64 " != GPU %016" PRIx64 " at step %" PRId64 "\n", cpu_hash,
                              gpu_hash, done);
    malloc_trim(0);
    rss_last = rss_kib(), heap_last = heap_kib();
    if (rss_first < 0) rss_first = rss_last;
    if (warming) rss_warm = rss_last, heap_warm = heap_last;
    std::printf("step %9" PRId64 "  energy %-12.6g  hash %016" PRIx64 "%s  rss %ld KiB  heap %ld KiB  %.0f s\n", done,
                e, cpu_hash, gpu ? (gpu_hash == cpu_hash ? " (cpu = gpu)" : " (CPU != GPU)") : "", rss_last, heap_last,
                std::chrono::duration<double>(clock::now() - start).count());
    std::fflush(stdout);
    if (failures > 10) break;
  }
  if (rss_last - rss_warm > kRssSlackKiB)
    ++failures, std::printf("FAIL: RSS grew from %ld KiB after the warm-up to %ld KiB\n", rss_warm, rss_last);
  if (heap_last - heap_warm > kHeapSlackKiB)
    ++failures, std::printf("FAIL: the heap in use grew from %ld KiB after the warm-up to %ld KiB\n", heap_warm,
                            heap_last);
  const double node_steps = static_cast<double>(model.nodes()) * static_cast<double>(done);
  std::printf("soak %s: %" PRId64 " steps in %.1f s (CPU %.1f s = %.0f M node-steps/s%s), energy %.6g .. %.6g "
              "(warm-up max %.6g), RSS %ld (first checkpoint) / %ld (warm-up end) -> %ld KiB, heap %ld -> %ld KiB, "
              "CPU and GPU %s\n",
              failures ? "FAILED" : "passed", done, std::chrono::duration<double>(clock::now() - start).count(),
              cpu_s, node_steps / cpu_s * 1e-6,
              gpu ? (", GPU " + std::to_string(static_cast<int>(gpu_s)) + " s = " +
                     std::to_string(static_cast<int>(node_steps / gpu_s * 1e-6)) + " M node-steps/s").c_str()
                  : "",
              e_min, e_max, warmup_max, rss_first, rss_warm, rss_last, heap_warm, heap_last,
              gpu ? (failures ? "compared at every checkpoint" : "bit-identical at every checkpoint") : "(GPU not run)");
  return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse_args(argc, argv, o)) return 2;
  try {
    return run(o);
  } catch (const std::exception& e) {  // InputError: the CPU solver refused a blow-up
    std::printf("FAIL: %s\n", e.what());
    return 1;
  }
}
