#pragma once
// The solver behind a session: the CPU reference solver (sim::CpuSolver) or the GPU compute solver
// (gpu::GpuSolver). Both advance the same model through the same step sequence, with the same bits
// in exact math. The session owns one; a front end chooses which with a SolverChoice.
#include <cstdint>
#include <string>
#include <vector>

#include "sim/backends.h"
#include "sim/model.h"
#include "sim/state.h"

namespace pond::sim {

class Solver {
 public:
  virtual ~Solver() = default;
  virtual const WaterModel& model() const = 0;
  virtual std::int64_t steps_done() const = 0;
  // Advances `steps` steps, each perturbation of the model applied just before its step.
  virtual void advance(std::int64_t steps) = 0;
  // A copy of the current state (the GPU solver reads it back).
  virtual WaterState read_state() const = 0;
  // Replaces the state and the step counter (the model's perturbations resume from that step).
  virtual void set_state(const WaterState& state, std::int64_t steps_done) = 0;
  // The bodies' current states (cheaper than read_state().bodies on the GPU).
  virtual std::vector<BodyState> read_bodies() const = 0;
  // Replaces the bodies' models (the same number of bodies; their states stay): a kinematic
  // body's new path, a body turned floating or kinematic. InputError for another count.
  virtual void set_body_models(std::vector<BodyModel> bodies) = 0;
  // What runs the steps, for messages: "avx2 x 2 threads", "gpu".
  virtual std::string engine() const = 0;
  // For a solver whose bit-identity with the CPU reference depends on the device: one line saying
  // whether it is guaranteed or only observed (empty: nothing to say, as for every CPU backend).
  virtual std::string identity() const { return {}; }
};

// Which solver advances the water. Switching at run time carries the state over.
struct SolverChoice {
  bool gpu = true;
  Backend backend = Backend::scalar;  // when !gpu
  int threads = 0;                    // when !gpu; 0 = all cores
  MathMode math = MathMode::exact;
};

}  // namespace pond::sim
