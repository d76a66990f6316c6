#pragma once
// The simulation session: the one piece of state every front end drives (`pond simulate`,
// `pond render`, the demo) and the renderer only reads. It owns the water of a scene (its spec with
// the edits made since), the model built from it, the solver (CPU backend or GPU) and its state,
// the wind (its ripples on the water, and the trees' gusts) and the sun, and every change to them:
// steps, splashes, physics edits (checked by the rules it is given: the scene file's), new
// constraints, bodies added, dragged and removed, a solver switch, reset, and the blow-up check.
// No Vulkan: the GPU solver comes from a factory the front end passes in (gpu/gpu_solvers.h).
//
// Nothing is lost when the GPU fails (GpuFailure: its device lost, its memory short): the session
// keeps a journal of what it did since the newest copy of the state the GPU solver left on the host
// (sim/solver_journal.h), and goes on on a CPU solver from that copy with the same bits, saying so
// through SessionSpec::notify. Its state can be saved and restored whole (image(), restore()).
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.h"
#include "sim/model.h"
#include "sim/rain.h"
#include "sim/solver.h"
#include "sim/solver_journal.h"
#include "sim/state.h"
#include "tree/wind.h"

namespace pond::sim {

// The rules run-time edits must pass, each throwing InputError naming what is wrong: the scene
// file's own checks (scene::session_spec fills them in). Empty: nothing is checked.
struct EditRules {
  // `physics` for `water` (whose floating bodies' densities it must keep stable).
  std::function<void(const Physics& physics, const WaterSpec& water)> physics;
  // A body that would join `water` as its body number water.bodies.size(), beside the bodies there
  // (now at `positions`, world units), on nodes of `kinds`.
  std::function<void(const BodySpec& body, const WaterSpec& water, const std::vector<std::uint8_t>& kinds,
                     const std::vector<std::array<double, 3>>& positions)>
      body;
};

// What a session simulates: the water, the wind over it and its trees, the sun.
struct SessionSpec {
  WaterSpec water;
  tree::WindSpec wind;
  std::size_t trees = 0;                   // tree instances the wind sways (each its own phase)
  std::array<double, 3> sun{};             // toward the sun (the scene's lighting.sun)
  EditRules rules;
  // Told once, in one line, when the session changes solver by itself (a GPU failure).
  std::function<void(const std::string&)> notify;
};

// Everything of a session that its spec (with the edits: water(), the wind's spec and sun()) does
// not say: the state and step count, the wind's and the rain's state, what was already reported.
// Session::restore() on a session made from the same spec continues exactly where image() left.
struct SessionImage {
  WaterSpec water;   // water() as saved: a held body let go where it is, at rest
  WaterState state;  // grid units, with the bodies
  std::int64_t steps = 0;
  std::int64_t ripples_until = 0;
  std::uint64_t clamp_reported = 0;
  Rain::Image rain;
  tree::Wind::Image wind;
};

class Session {
 public:
  // Starts from rest at step 0. InputError for a CPU backend this machine lacks; InternalError
  // for a GPU choice without a factory.
  Session(SessionSpec spec, SolverChoice choice, GpuSolverFactory gpu = {});
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Advances `steps` steps; the scene's perturbations and wind ripples land just before their step.
  // With the GPU solver this submits the work and returns (solver.h: displacements() waits).
  void advance(std::int64_t steps);
  // A splash applied to the current state now (its `step` is ignored); row/col in grid indices.
  // With the GPU solver a dispatch in its next submission, never a round trip of the state.
  void splash(const Perturbation& splash);
  // This frame's rain (sim/rain.h): `drops_per_frame` on average, each a splash of `radius` and
  // about `amplitude` (world units).
  void rain(double drops_per_frame, double radius, double amplitude) {
    for (const Perturbation& p : rain_.drops(model(), drops_per_frame, radius, amplitude)) splash(p);
  }
  // New physics for the same grid, refused (InputError, nothing changed) by the rules; the state
  // carries over.
  void set_physics(const Physics& physics);
  // New constraints or border for the same grid (the demo's modes): the state carries over and
  // obeys them at once (fixed nodes at rest, vertical-only nodes without horizontal motion). The
  // physics stays the session's. InternalError for another grid.
  void set_water(const WaterSpec& water);
  void set_solver(SolverChoice choice);  // the state and the step count carry over
  // Where GPU solvers come from from now on (a front end that made its device again after a loss);
  // the session must not be on a GPU solver of the old factory (recover() first).
  void set_gpu_factory(GpuSolverFactory gpu);

  // The bodies (grid units). Their specs are water().bodies, with the edits below. Not const, as
  // state() below: the GPU solver waits for its last submission, and when the GPU fails while they
  // read, the session goes on on the CPU.
  std::vector<BodyState> bodies();
  // Adds a body where its spec puts it (InputError from the rules: a radius below the grid
  // spacing, a position off the grid, too many bodies, ...). The water carries over.
  void add_body(const BodySpec& body);
  void remove_body(std::size_t index);
  // Holds body `index` and moves it, kinematic, from where it is to `target` (world units) over the
  // next `steps` steps (at least 1); call again to move it on.
  void drag_body(std::size_t index, const std::array<double, 3>& target, std::int64_t steps);
  // Lets a held body go where it is: a floating body floats again with `velocity` (world units),
  // a kinematic one stays there.
  void release_body(std::size_t index, const std::array<double, 3>& velocity);
  bool held(std::size_t index) const { return index < held_.size() && held_[index].has_value(); }
  // One line naming the bodies of `bodies` (this session's, as bodies() gave them) whose speed was
  // clamped (shared::kBodyClamped) and not yet named by an earlier call; "" when there are none.
  std::string clamp_notice(const std::vector<BodyState>& bodies);
  void reset();                          // rest, step 0: the scene's perturbations replay
  // Replaces the state and the step count (same grid; InternalError otherwise).
  void set_state(const WaterState& state, std::int64_t steps);
  // The state after the blow-up check (the CPU solver stops at the step it blows up, the GPU
  // solver does not stop to look): InputError naming the first node whose velocity is not finite.
  WaterState finite_state();

  // The trees' wind: by default its clock is the simulated time, moved by catch_up_wind(); the
  // demo moves it in real time with advance_wind(). The controls change the user's wind.
  void catch_up_wind() { wind_.advance(simulated_seconds() - wind_.time()); }
  void advance_wind(double seconds) { wind_.advance(seconds); }
  void set_wind_direction(double radians) { wind_.set_direction(radians); }
  void set_wind_strength(double strength) { wind_.set_strength(strength); }
  const tree::Wind& wind() const { return wind_; }
  // The direction toward the sun; the caller has checked it (scene::check_sun).
  void set_sun(const std::array<double, 3>& toward_sun) { sun_ = toward_sun; }
  const std::array<double, 3>& sun() const { return sun_; }

  const WaterSpec& water() const { return water_; }  // with the edits made since
  const WaterModel& model() const { return solver_->model(); }
  const SolverChoice& choice() const { return choice_; }
  std::int64_t steps_done() const { return solver_->steps_done(); }
  double simulated_seconds() const { return static_cast<double>(steps_done()) * water_.physics.dt; }
  WaterState state();  // reads it back from the GPU solver, waiting
  // After a GPU failure elsewhere (the renderer's: the device is lost for everyone), the session
  // goes on on the CPU from its journal, if the GPU solver did not already.
  void recover(const GpuFailure& failure);

  // The spec's part that restore() cannot take: the water with its edits (water()), the wind's
  // spec as the scene gave it (ripples_spec(), which the ripples follow) and the sun.
  const tree::WindSpec& ripples_spec() const { return wind_spec_; }
  // Everything else, with the water (a body held by drag_body() is saved let go, at rest).
  SessionImage image();
  // Takes an image of a session made from the same spec (InputError naming what does not fit).
  void restore(const SessionImage& image);
  // The solver, for what the host holds without asking it (its model, its step count).
  const Solver& solver() const { return *solver_; }
  // Its readers that may wait (a renderer's frame: its one wait), and nothing that changes the
  // state, which changes only through the session.
  SolverReader reader() { return SolverReader(*solver_); }
  // Whether every solver of the session keeps its tile bounds (solver.h), for a renderer's LOD.
  void track_tile_bounds(bool on);
  // Grows whenever solver() is replaced (a drawer holding its buffers must let go), and whenever
  // the state changes, respectively.
  std::uint64_t solver_generation() const { return solver_generation_; }
  std::uint64_t state_revision() const { return state_revision_; }

 private:
  WaterModel build() const;
  // `model` (from build()) with `state` at `steps`; the solver the choice says (the CPU's when the
  // GPU's cannot be made: the failure is told).
  void replace_solver(WaterModel model, const WaterState& state, std::int64_t steps);
  // The solver's state replaced (and its bodies' models, unless empty), the GPU's failure survived.
  void put_state(const WaterState& state, std::int64_t steps, std::vector<BodyModel> bodies);
  // The CPU's widest backend chosen after `failure`, and told.
  void choose_cpu(const GpuFailure& failure);
  // After `failure` of the GPU solver: a CPU solver from its host copy and the journal.
  void fail_over(const GpuFailure& failure);
  // Calls `read` on the solver; on a GPU failure, fails over and calls it again.
  template <class F>
  auto guarded(F&& read);
  // Keeps the journal short: forgets what the solver's host copy already holds.
  void trim_journal();
  bool journaling() const { return choice_.gpu; }

  WaterSpec water_;
  tree::WindSpec wind_spec_;  // the scene's, for the ripples (a pure function of it and the step)
  EditRules rules_;
  SolverChoice choice_;
  GpuSolverFactory gpu_;
  std::int64_t ripples_until_ = 0;  // the model holds the wind ripples of steps below this
  std::vector<std::optional<BodySpec>> held_;  // per body: its spec before drag_body() took it
  std::uint64_t clamp_reported_ = 0;           // bit b: clamp_notice() named body b
  bool track_tiles_ = false;
  std::unique_ptr<Solver> solver_;
  tree::Wind wind_;
  std::array<double, 3> sun_;
  Rain rain_;
  std::function<void(const std::string&)> notify_;
  SolverJournal journal_;  // while the GPU solves
  std::uint64_t solver_generation_ = 0, state_revision_ = 0;
};

}  // namespace pond::sim
