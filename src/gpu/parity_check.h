#pragma once
// The lockstep comparison of the parity suite and `pond check`: the CPU scalar solver (one thread, the reference)
// and the GPU solver run the same model from rest; every `checkpoint` steps their states are
// compared bit for bit. On a difference the run bisects: both solvers restart from the last equal
// checkpoint and advance one step at a time to the first differing step, and the report names it,
// the first differing node (row, col, component) and both values in hex.
//
// Bit-dump mode (like Jolt's determinism log): with POND_PARITY_LOG=<file> every compared step
// appends "<scene> step <n> cpu <hash> gpu <hash>" to the file, so two runs (two machines, two
// drivers, two commits) can be diffed; POND_PARITY_EVERY_STEP=1 compares after every step.
#include <cstdint>
#include <optional>
#include <string>

#include "gpu/context.h"
#include "gpu/gpu_solver.h"
#include "sim/model.h"
#include "sim/state.h"

namespace pond::gpu {

struct Difference {
  std::int64_t step = 0;  // the state after this many steps differs
  std::size_t node = 0;  // or the body's index
  int component = 0;     // 0..5 = ux uy uz vx vy vz (a body's x y z vx vy vz)
  float cpu = 0, gpu = 0;
  bool body = false;     // the water is equal and body `node` differs
  bool count = false;    // the numbers of nodes (with `body`: of bodies) differ: cpu_count, gpu_count
  std::size_t cpu_count = 0, gpu_count = 0;
};

// The first difference of two states: the numbers of nodes, then the first differing node by node
// then component, then the numbers of bodies, then the first differing body; nullopt when equal bit
// for bit. A body that one state has and the other lacks is a difference like any other.
std::optional<Difference> first_difference(const sim::WaterState& cpu, const sim::WaterState& gpu);

std::string describe(const Difference& d, const sim::WaterModel& model);

// Runs `steps` steps on both solvers; nullopt when the states are equal after every checkpoint.
// `gpu_model` (default: `model`) lets a test give the GPU a deliberately different model to prove
// that the bisection finds the step.
std::optional<Difference> run_parity(const Context& ctx, const sim::WaterModel& model, std::int64_t steps,
                                     std::int64_t checkpoint, const std::string& tag,
                                     const sim::WaterModel* gpu_model = nullptr);

}  // namespace pond::gpu
