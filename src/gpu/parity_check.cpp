#include "gpu/parity_check.h"

#include <algorithm>
#include <bit>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "gpu/gpu_solver.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"

namespace pond::gpu {
namespace {

const float* component(const sim::WaterState& s, int c) {
  const float* all[6] = {s.ux.data(), s.uy.data(), s.uz.data(), s.vx.data(), s.vy.data(), s.vz.data()};
  return all[c];
}

class ParityLog {
 public:
  ParityLog() {
    if (const char* path = std::getenv("POND_PARITY_LOG")) file_ = std::fopen(path, "a");
  }
  ~ParityLog() {
    if (file_) std::fclose(file_);
  }
  void line(const std::string& tag, std::int64_t step, const sim::WaterState& cpu, const sim::WaterState& gpu,
            const sim::WaterModel& m) {
    if (!file_) return;
    std::fprintf(file_, "%s step %" PRId64 " cpu %016" PRIx64 " gpu %016" PRIx64 "\n", tag.c_str(), step,
                 sim::state_hash(cpu, m), sim::state_hash(gpu, m));
  }

 private:
  std::FILE* file_ = nullptr;
};

}  // namespace

std::optional<Difference> first_difference(const sim::WaterState& cpu, const sim::WaterState& gpu) {
  if (cpu.nodes() != gpu.nodes())
    return Difference{.node = std::min(cpu.nodes(), gpu.nodes()), .count = true, .cpu_count = cpu.nodes(),
                      .gpu_count = gpu.nodes()};
  for (std::size_t n = 0; n < cpu.nodes(); ++n)
    for (int c = 0; c < 6; ++c) {
      const float a = component(cpu, c)[n], b = component(gpu, c)[n];
      if (std::bit_cast<std::uint32_t>(a) != std::bit_cast<std::uint32_t>(b))
        return Difference{.step = 0, .node = n, .component = c, .cpu = a, .gpu = b};
    }
  if (cpu.bodies.size() != gpu.bodies.size())
    return Difference{.node = std::min(cpu.bodies.size(), gpu.bodies.size()), .body = true, .count = true,
                      .cpu_count = cpu.bodies.size(), .gpu_count = gpu.bodies.size()};
  for (std::size_t k = 0; k < cpu.bodies.size(); ++k) {
    const sim::BodyState &p = cpu.bodies[k], &q = gpu.bodies[k];
    const float a[6] = {p.x, p.y, p.z, p.vx, p.vy, p.vz}, b[6] = {q.x, q.y, q.z, q.vx, q.vy, q.vz};
    for (int c = 0; c < 6; ++c)
      if (std::bit_cast<std::uint32_t>(a[c]) != std::bit_cast<std::uint32_t>(b[c]))
        return Difference{.step = 0, .node = k, .component = c, .cpu = a[c], .gpu = b[c], .body = true};
  }
  return std::nullopt;
}

std::string describe(const Difference& d, const sim::WaterModel& m) {
  static const char* names[6] = {"ux", "uy", "uz", "vx", "vy", "vz"};
  static const char* body_names[6] = {"x", "y", "z", "vx", "vy", "vz"};
  char text[256];
  if (d.count) {
    std::snprintf(text, sizeof text, "after step %" PRId64 " the states hold different numbers of %s: cpu %zu, gpu %zu",
                  d.step, d.body ? "bodies" : "nodes", d.cpu_count, d.gpu_count);
    return text;
  }
  if (d.body) {
    std::snprintf(text, sizeof text, "first difference after step %" PRId64 " at body %zu %s: cpu %a (0x%08x) gpu %a (0x%08x)",
                  d.step, d.node, body_names[d.component], static_cast<double>(d.cpu), std::bit_cast<std::uint32_t>(d.cpu),
                  static_cast<double>(d.gpu), std::bit_cast<std::uint32_t>(d.gpu));
    return text;
  }
  std::snprintf(text, sizeof text,
                "first difference after step %" PRId64 " at node %zu (row %zu, col %zu) %s: cpu %a (0x%08x) gpu %a (0x%08x)",
                d.step, d.node, d.node / static_cast<std::size_t>(m.cols), d.node % static_cast<std::size_t>(m.cols),
                names[d.component], static_cast<double>(d.cpu), std::bit_cast<std::uint32_t>(d.cpu),
                static_cast<double>(d.gpu), std::bit_cast<std::uint32_t>(d.gpu));
  return text;
}

std::optional<Difference> run_parity(const Context& ctx, const sim::WaterModel& model, std::int64_t steps,
                                     std::int64_t checkpoint, const std::string& tag,
                                     const sim::WaterModel* gpu_model) {
  if (const char* every = std::getenv("POND_PARITY_EVERY_STEP"); every && std::strcmp(every, "1") == 0) checkpoint = 1;
  ParityLog log;
  sim::CpuSolver cpu(model, sim::Backend::scalar, 1);
  GpuSolver gpu(ctx, gpu_model ? *gpu_model : model);
  sim::WaterState last_equal = cpu.state();
  std::int64_t last_equal_step = 0;
  while (cpu.steps_done() < steps) {
    const std::int64_t n = std::min(checkpoint, steps - cpu.steps_done());
    cpu.advance(n);
    gpu.advance(n);
    const sim::WaterState g = gpu.read_state();
    log.line(tag, cpu.steps_done(), cpu.state(), g, model);
    if (!first_difference(cpu.state(), g)) {
      last_equal = cpu.state();
      last_equal_step = cpu.steps_done();
      continue;
    }
    // Bisect: replay from the last equal checkpoint one step at a time.
    cpu.set_state(last_equal, last_equal_step);
    gpu.set_state(last_equal, last_equal_step);
    while (true) {
      cpu.advance(1);
      gpu.advance(1);
      const sim::WaterState gs = gpu.read_state();
      log.line(tag + " (bisect)", cpu.steps_done(), cpu.state(), gs, model);
      if (auto d = first_difference(cpu.state(), gs)) {
        d->step = cpu.steps_done();
        return d;
      }
    }
  }
  return std::nullopt;
}

}  // namespace pond::gpu
