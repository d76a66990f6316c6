#include "app/bench/cpu_figures.h"

#include <chrono>
#include <cstdio>
#include <map>
#include <thread>

#include "app/bench/workloads.h"
#include "lod/lod_builder.h"
#include "lod/node_positions.h"
#include "lod/tile_ranges.h"
#include "sim/backends.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"

namespace pond::bench {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string grid_text(int size) { return std::to_string(size) + "²"; }

}  // namespace

std::string hex_hash(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

void measure_cpu_solver(const Plan& plan, Progress& progress, Report& report) {
  const int all = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<int> thread_counts = {1};
  if (all > 1) thread_counts.push_back(all);
  for (const int size : plan.solver_sizes()) {
    const sim::WaterModel model = rippled_model(size, sim::MathMode::exact);
    const std::int64_t steps = steps_per_sample(size, plan.node_steps_per_sample());
    std::map<std::string, std::string> hashes;  // per backend and threads, for the message
    for (const sim::Backend backend : {sim::Backend::scalar, sim::Backend::sse, sim::Backend::avx2, sim::Backend::avx512}) {
      if (!sim::cpu_supports(backend)) continue;
      for (const int threads : thread_counts) {
        const std::string label = std::string(sim::backend_name(backend)) + ", " + std::to_string(threads) +
                                  (threads == 1 ? " thread, " : " threads, ") + grid_text(size);
        progress.show("CPU solver, " + label);
        sim::CpuSolver solver(model, backend, threads);
        solver.advance(kWarmSteps);
        Figure f = make_figure(std::string("cpu.") + sim::backend_name(backend) + ".t" + std::to_string(threads) + "." +
                         std::to_string(size), "CPU solver, " + label, "node-steps/s");
        for (int r = 0; r < plan.repeats(); ++r) {
          const auto t0 = Clock::now();
          solver.advance(steps);
          f.samples.push_back(double(size) * size * double(steps) / seconds_since(t0));
        }
        f.hash = hex_hash(sim::state_hash(solver.state(), solver.model()));
        hashes[label] = *f.hash;
        report.add(std::move(f));
      }
    }
    for (const auto& [label, hash] : hashes)
      if (hash != hashes.begin()->second) {
        report.hashes_agree = false;
        report.notes.push_back("state hashes differ at " + grid_text(size) + ": " + hashes.begin()->first + " " +
                               hashes.begin()->second + ", " + label + " " + hash);
      }
  }
}

void note_gpu_hashes(const Plan& plan, Report& report) {
  for (const int size : plan.solver_sizes()) {
    const Figure* cpu = report.find("cpu.scalar.t1." + std::to_string(size));
    const Figure* gpu = report.find("gpu.exact." + std::to_string(size));
    if (cpu && gpu && cpu->hash != gpu->hash)
      report.notes.push_back("the GPU's exact state at " + grid_text(size) + " (" + *gpu->hash + ") is not the CPU's (" +
                             *cpu->hash + "): run `pond check` on this device");
  }
}

void measure_lod(const Plan& plan, Progress& progress, Report& report) {
  for (const int side : plan.lod_sizes()) {
    progress.show("LOD build, rain, " + grid_text(side) + " (simulating the rain)");
    const std::vector<float> state = rain_state(side);
    const lod::NodePositions positions = lod::interleaved_positions(state.data(), side, side);
    const lod::TileRanges ranges = lod::tile_ranges(positions);  // what a running solver hands the LOD
    progress.show("LOD build, rain, " + grid_text(side));
    lod::LodBuilder builder(side, side);
    std::vector<std::uint32_t> out(builder.max_indices());
    const lod::Camera camera = rain_camera(side);
    // Each sample: the mean of a batch of builds of at least kBatchSeconds together (at least one).
    constexpr double kBatchSeconds = 0.02;
    auto t0 = Clock::now();
    std::size_t indices = builder.build(positions, ranges, camera, 1.0, out);
    const int batch = std::max(1, static_cast<int>(kBatchSeconds / std::max(seconds_since(t0), 1e-6)));
    Figure f = make_figure("lod." + std::to_string(side), "LOD build, rain, " + grid_text(side) + ", 1280x720, 1 px, 1 thread", "ms", false);
    for (int r = 0; r < 2 * plan.repeats() - 1; ++r) {  // builds are short: more samples
      t0 = Clock::now();
      for (int k = 0; k < batch; ++k) indices = builder.build(positions, ranges, camera, 1.0, out);
      f.samples.push_back(1e3 * seconds_since(t0) / batch);
    }
    f.triangles = static_cast<std::int64_t>(indices / 3);
    report.add(std::move(f));
  }
}

void measure_cpu_bodies(const Plan& plan, Progress& progress, Report& report) {
  const int side = plan.bodies_grid();
  const std::int64_t steps = plan.quick ? 4 : 16;
  for (const int count : {8, 64}) {
    progress.show("bodies on the CPU solver, " + std::to_string(count) + " at " + grid_text(side));
    sim::CpuSolver plain(bodies_model(side, 0), sim::best_backend(), 0);
    sim::CpuSolver bodies(bodies_model(side, count), sim::best_backend(), 0);
    plain.advance(steps);
    bodies.advance(steps);
    Figure f = make_figure("bodies.cpu." + std::to_string(count), std::to_string(count) + " bodies, a step with / without, " + plain.engine() + ", " + grid_text(side), "x", false);
    for (int r = 0; r < plan.repeats() + 2; ++r) {  // a ratio of two short runs: a few more samples
      double with = 0, without = 0;
      for (int k = 0; k < (plan.quick ? 4 : 8); ++k) {  // alternated: a shared machine's load falls on both alike
        auto t0 = Clock::now();
        plain.advance(steps);
        without += seconds_since(t0);
        t0 = Clock::now();
        bodies.advance(steps);
        with += seconds_since(t0);
      }
      f.samples.push_back(with / without);
    }
    report.add(std::move(f));
  }
}

}  // namespace pond::bench
