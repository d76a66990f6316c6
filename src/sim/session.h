#pragma once
// The simulation session: the one piece of state every front end drives (`pond simulate`,
// `pond render`, the demo). It owns the scene's water, the model built from it, the solver (CPU
// backend or GPU) and its state, and every change to them: steps, splashes, the scene's wind
// ripples, physics edits (checked by the scene file's own checks), new constraints, a solver
// switch, reset, and the blow-up check. No Vulkan: the GPU solver comes from a factory the front end
// passes in (gpu::GpuSolver), and the renderer reads the solver it is given.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "scene/scene.h"
#include "sim/model.h"
#include "sim/solver.h"
#include "sim/state.h"

namespace pond::sim {

// Makes the GPU solver of a model (the front end's: it owns the Vulkan device).
using GpuSolverFactory = std::function<std::unique_ptr<Solver>(const WaterModel& model)>;

class Session {
 public:
  // Starts from rest at step 0. InputError for a CPU backend this machine lacks or a GPU choice
  // without a factory.
  Session(scene::Scene scene, SolverChoice choice, GpuSolverFactory gpu = {});
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Called before the session changes the water other than by stepping it (a splash, an edit, a
  // new solver, a new state): a renderer still reading the solver's buffers waits for them there.
  void set_before_change(std::function<void()> hook) { before_change_ = std::move(hook); }

  // Advances `steps` steps; the scene's perturbations and wind ripples land just before their step.
  void advance(std::int64_t steps);
  // A splash applied to the current state now (its `step` is ignored); row/col in grid indices.
  void splash(const Perturbation& splash);
  // New physics for the same grid, refused (InputError, nothing changed) by the scene file's own
  // checks; the state carries over.
  void set_physics(const Physics& physics);
  // New constraints or border for the same grid (the demo's modes): the state carries over and
  // obeys them at once (fixed nodes at rest, vertical-only nodes without horizontal motion). The
  // physics stays the session's. InputError for another grid.
  void set_water(const WaterSpec& water);
  void set_solver(SolverChoice choice);  // the state and the step count carry over

  // The bodies (world units). Their specs are scene().bodies, with the edits below.
  std::vector<BodyState> bodies() const { return solver_->read_bodies(); }  // grid units
  // Adds a body where its spec puts it (InputError: a radius below the grid spacing, a mass that
  // is not positive, a position off the grid, more than 64 bodies). The water carries over.
  void add_body(const BodySpec& body);
  void remove_body(std::size_t index);
  // Holds body `index` and moves it, kinematic, from where it is to `target` (world units) over the
  // next `steps` steps (at least 1); call again to move it on.
  void drag_body(std::size_t index, const std::array<double, 3>& target, std::int64_t steps);
  // Lets a held body go where it is: a floating body floats again with `velocity` (world units),
  // a kinematic one stays there.
  void release_body(std::size_t index, const std::array<double, 3>& velocity);
  bool held(std::size_t index) const { return index < held_.size() && held_[index].has_value(); }
  void reset();                          // rest, step 0: the scene's perturbations replay
  // Replaces the state and the step count (same grid; InputError otherwise).
  void set_state(const WaterState& state, std::int64_t steps);
  // The state after the blow-up check (the CPU solver stops at the step it blows up, the GPU
  // solver does not stop to look): InputError naming the first node whose velocity is not finite.
  WaterState finite_state() const;

  const scene::Scene& scene() const { return scene_; }  // with the edits made since
  const WaterModel& model() const { return solver_->model(); }
  const SolverChoice& choice() const { return choice_; }
  std::int64_t steps_done() const { return solver_->steps_done(); }
  WaterState state() const { return solver_->read_state(); }
  const Solver& solver() const { return *solver_; }
  Solver& solver() { return *solver_; }  // the renderer's: the GPU solver computes its normals
  // Grows whenever solver() is replaced (a drawer holding its buffers must let go), and whenever
  // the state changes, respectively.
  std::uint64_t solver_generation() const { return solver_generation_; }
  std::uint64_t state_revision() const { return state_revision_; }

 private:
  WaterModel build() const;
  void notify_change() const {
    if (before_change_) before_change_();
  }
  // `model` (from build()) with `state` at `steps`; the solver the choice says.
  void replace_solver(WaterModel model, const WaterState& state, std::int64_t steps);

  scene::Scene scene_;
  SolverChoice choice_;
  GpuSolverFactory gpu_;
  std::int64_t ripples_until_ = 0;  // the model holds the wind ripples of steps below this
  std::function<void()> before_change_;
  std::vector<std::optional<BodySpec>> held_;  // per body: its spec before drag_body() took it
  std::unique_ptr<Solver> solver_;
  std::uint64_t solver_generation_ = 0, state_revision_ = 0;
};

}  // namespace pond::sim
