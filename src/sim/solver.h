#pragma once
// The solver behind a session: the CPU reference solver (sim::CpuSolver) or the GPU compute solver
// (gpu::GpuSolver). Both advance the same model through the same step sequence, with the same bits
// in exact math. The session owns one; a front end chooses which with a SolverChoice.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/node_runs.h"
#include "sim/backends.h"
#include "sim/model.h"
#include "sim/state.h"
#include "sim/tile_bounds.h"

namespace pond::sim {

// The displacements (grid units, sim/state.h) of a solver's current state where the host can read
// them: node (i, j) at i * pitch + j of each array.
struct HostDisplacements {
  const float* ux = nullptr;
  const float* uy = nullptr;
  const float* uz = nullptr;
  std::size_t pitch = 0;
};

// A state the host holds a copy of, `step` steps done (sim/solver_journal.h).
struct HostSnapshot {
  WaterState state;
  std::int64_t step = 0;
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual const WaterModel& model() const = 0;
  virtual std::int64_t steps_done() const = 0;
  // Advances `steps` steps, each perturbation of the model applied just before its step.
  virtual void advance(std::int64_t steps) = 0;
  // Applies a perturbation (any step) to the current state, as if it were scheduled just before
  // the next step: the GPU solver records its dispatch into its next submission, no round trip.
  virtual void perturb(const PerturbationTable& table) = 0;
  // Not const, every reader of the state below: the GPU solver's reads submit and wait, and a
  // caller must hold the solver as one that may (a const Solver& reads only what is on the host).
  // A copy of the current state (the GPU solver reads it back and waits).
  virtual WaterState read_state() = 0;
  // The current state's displacements on the host, valid until the next call that changes the
  // state. The GPU solver copies them in every submission that changes the state and waits here
  // for its last one: in a frame, the one wait for the GPU. Its perturbations not yet submitted
  // (they go with the next advance(), which may be of 0 steps) are not in them yet.
  virtual HostDisplacements displacements() = 0;
  // Replaces the state and the step counter (the model's perturbations resume from that step).
  virtual void set_state(const WaterState& state, std::int64_t steps_done) = 0;
  // The bodies' current states (the GPU solver copies them in every submission, so this waits for
  // its last one, as displacements() does, and reads a few bytes).
  virtual std::vector<BodyState> read_bodies() = 0;
  // Replaces the bodies' models (the same number of bodies; their states stay): a kinematic
  // body's new path, a body turned floating or kinematic. InputError for another count.
  virtual void set_body_models(std::vector<BodyModel> bodies) = 0;
  // Which nodes displacements() must hold after each later submission: every node (nullopt, the
  // default) or at least those of `windows` (within the grid). The GPU solver then copies only
  // those to the host where it cannot read the state in place; every other solver holds them all.
  virtual void keep_on_host(std::optional<std::vector<core::GridWindow>> windows) { (void)windows; }
  // Whether displacements() holds every node of `w` now (the GPU solver waits for its last
  // submission first, as displacements() does).
  virtual bool holds_on_host(const core::GridWindow& w) { (void)w; return true; }
  // Makes displacements() hold the nodes of `windows` of the current state too (the GPU solver
  // copies those it lacks and waits).
  virtual void bring_to_host(std::span<const core::GridWindow> windows) { (void)windows; }
  // displacements() holding every node.
  HostDisplacements all_displacements() {
    const core::GridWindow all{0, 0, model().rows, model().cols};
    bring_to_host(std::span(&all, 1));
    return displacements();
  }
  // Whether to keep the current state's tile bounds (shared/tile_bounds.h), which the LOD builder
  // descends instead of reading every node; off by default, and then free.
  virtual void track_tile_bounds(bool on) { (void)on; }
  // Those bounds while tracked, valid as displacements() is; empty when not tracked or where the
  // solver keeps none.
  virtual std::span<const TileBounds> tile_bounds() { return {}; }
  // The newest copy of this solver's state that the host holds, for a solver that can fail (the GPU
  // solver: GpuFailure): a CPU solver can go on from it (sim/solver_journal.h). Null for a solver
  // that cannot fail (the CPU solver: its state is the host's).
  virtual const HostSnapshot* host_snapshot() { return nullptr; }
  // What runs the steps, for messages: "avx2 x 2 threads", "gpu".
  virtual std::string engine() const = 0;
  // For a solver whose bit-identity with the CPU reference depends on the device: one line saying
  // whether it is guaranteed or only observed (empty: nothing to say, as for every CPU backend).
  virtual std::string identity() const { return {}; }
};

// A solver's readers that may wait, and nothing that changes its state: what a session hands those
// who read its water (Session::reader: a frame's one wait, the LOD's nodes, picking), so that no
// one steps or replaces the state behind the session's back.
class SolverReader {
 public:
  explicit SolverReader(Solver& solver) : solver_(solver) {}
  HostDisplacements displacements() { return solver_.displacements(); }
  HostDisplacements all_displacements() { return solver_.all_displacements(); }
  std::span<const TileBounds> tile_bounds() { return solver_.tile_bounds(); }
  std::vector<BodyState> read_bodies() { return solver_.read_bodies(); }
  void keep_on_host(std::optional<std::vector<core::GridWindow>> windows) { solver_.keep_on_host(std::move(windows)); }
  bool holds_on_host(const core::GridWindow& w) { return solver_.holds_on_host(w); }
  void bring_to_host(std::span<const core::GridWindow> windows) { solver_.bring_to_host(windows); }

 private:
  Solver& solver_;
};

// Makes the GPU solver of a model (the front end's: it owns the Vulkan device; gpu/gpu_solvers.h).
using GpuSolverFactory = std::function<std::unique_ptr<Solver>(const WaterModel& model)>;

// Which solver advances the water. Switching at run time carries the state over.
struct SolverChoice {
  bool gpu = true;
  Backend backend = Backend::scalar;  // when !gpu
  int threads = 0;                    // when !gpu; 0 = all cores
  MathMode math = MathMode::exact;
};

}  // namespace pond::sim
