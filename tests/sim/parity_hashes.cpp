// The parity suite's scenes (sim/parity_cases.h) on one CPU backend, no GPU needed: one line a
// scene, "NAME STEPS WATER_HASH BODIES_HASH", so that two machines' runs can be compared line by
// line (tests/sim/cross_parity_test.sh: aarch64 scalar and neon under qemu against x86-64 scalar).
// Usage: parity_hashes [--solver NAME] [--scale S] [--threads N]
//   --scale S (0 < S <= 1): each scene runs S times its parity length (at least one step), as
//   POND_PARITY_STEP_SCALE does for the GPU suite.
#include <algorithm>
#include <bit>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "core/errors.h"
#include "scene/scene.h"
#include "sim/backends.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"
#include "sim/parity_cases.h"

namespace {

[[noreturn]] void bad(const std::string& what) {
  std::fprintf(stderr, "parity_hashes: %s\n", what.c_str());
  std::exit(2);
}

double number(const char* text, const char* flag) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (*text == '\0' || *end != '\0') bad(std::string(flag) + " takes a number, not '" + text + "'");
  return v;
}

// FNV-1a 64 over the bodies' states, field by field (their bits).
std::uint64_t bodies_hash(const pond::sim::WaterState& s) {
  std::vector<float> fields;
  for (const auto& b : s.bodies)
    fields.insert(fields.end(), {b.x, b.y, b.z, b.vx, b.vy, b.vz, std::bit_cast<float>(b.flags)});
  return pond::sim::state_hash(fields);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace pond;
  std::string solver = "scalar";
  double scale = 1;
  int threads = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) bad(flag + ": expected a value after it (--solver, --scale, --threads)");
    const char* value = argv[++i];
    if (flag == "--solver") solver = value;
    else if (flag == "--scale") scale = number(value, "--scale");
    else if (flag == "--threads") threads = static_cast<int>(number(value, "--threads"));
    else bad("unknown option " + flag + " (--solver, --scale, --threads)");
  }
  if (!(scale > 0 && scale <= 1)) bad("--scale must be in (0, 1]");
  if (threads < 1 || threads > 64) bad("--threads must be in [1, 64]");
  const auto backend = sim::parse_backend(solver);
  if (!backend) bad("unknown solver '" + solver + "'");
  try {
    for (const test::ParityCase& c : test::kCases) {
      const scene::Scene scene = *c.json ? scene::parse_scene(c.json, c.name) : scene::load_scene("");
      sim::CpuSolver run(sim::build_model(scene), *backend, threads);
      const std::int64_t steps = std::max<std::int64_t>(1, std::llround(static_cast<double>(c.steps) * scale));
      run.advance(steps);
      std::printf("%s %" PRId64 " %016" PRIx64 " %016" PRIx64 "\n", c.name, steps,
                  sim::state_hash(run.state(), run.model()), bodies_hash(run.state()));
      std::fflush(stdout);
    }
  } catch (const InputError& e) {
    bad(e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "parity_hashes: %s\n", e.what());
    return 1;
  }
  return 0;
}
