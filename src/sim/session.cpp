#include "sim/session.h"

#include <algorithm>

#include "core/errors.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"
#include "sim/perturbation.h"
#include "sim/wind_ripples.h"

namespace pond::sim {
namespace {

// The wind ripples are scheduled perturbations of the model, tabulated this many steps ahead; a
// run past them rebuilds the solver with the next ones (the same ripples, so the same bits).
constexpr std::int64_t kRippleHorizonSteps = 16384;

// A state taken over by new constraints obeys them from the start: fixed nodes at rest,
// vertical-only nodes without horizontal displacement or velocity.
void constrain(WaterState& s, const WaterModel& model) {
  for (std::size_t n = 0; n < s.nodes(); ++n) {
    const auto kind = static_cast<NodeKind>(model.kinds[n]);
    if (kind == NodeKind::free) continue;
    s.ux[n] = s.uz[n] = s.vx[n] = s.vz[n] = 0;
    if (kind == NodeKind::fixed) s.uy[n] = s.vy[n] = 0;
  }
}

}  // namespace

Session::Session(scene::Scene scene, SolverChoice choice, GpuSolverFactory gpu)
    : scene_(std::move(scene)), choice_(choice), gpu_(std::move(gpu)) {
  if (scene_.wind.ripples) ripples_until_ = kRippleHorizonSteps;
  WaterModel model = build();
  const WaterState rest = rest_state(model);
  replace_solver(std::move(model), rest, 0);
}

Session::~Session() = default;

WaterModel Session::build() const {
  WaterSpec water = scene_;
  add_wind_ripples(water, scene_.wind, ripples_until_);
  return build_model(water, choice_.math);
}

void Session::replace_solver(WaterModel model, const WaterState& state, std::int64_t steps) {
  if (state.nodes() != model.nodes())
    throw InputError("the state has " + std::to_string(state.nodes()) + " nodes, the grid " +
                     std::to_string(model.nodes()));
  notify_change();
  std::unique_ptr<Solver> next;
  if (choice_.gpu) {
    if (!gpu_) throw InputError("the GPU solver is not available here");
    solver_.reset();  // one solver's buffers at a time
    next = gpu_(model);
  } else {
    next = std::make_unique<CpuSolver>(std::move(model), choice_.backend, choice_.threads);
  }
  next->set_state(state, steps);
  solver_ = std::move(next);
  ++solver_generation_;
  ++state_revision_;
}

void Session::advance(std::int64_t steps) {
  if (steps <= 0) return;
  const std::int64_t end = solver_->steps_done() + steps;
  if (scene_.wind.ripples && end > ripples_until_) {
    ripples_until_ = end + kRippleHorizonSteps;
    replace_solver(build(), solver_->read_state(), solver_->steps_done());
  }
  solver_->advance(steps);
  ++state_revision_;
}

void Session::splash(const Perturbation& splash) {
  WaterState state = solver_->read_state();
  apply_perturbation(tabulate(splash, solver_->model()), state);
  notify_change();
  solver_->set_state(state, solver_->steps_done());
  ++state_revision_;
}

void Session::set_physics(const Physics& physics) {
  scene::check_physics(physics);
  const WaterState state = solver_->read_state();
  const std::int64_t steps = solver_->steps_done();
  scene_.physics = physics;
  replace_solver(build(), state, steps);
}

void Session::set_water(const WaterSpec& water) {
  if (water.grid.rows != scene_.grid.rows || water.grid.cols != scene_.grid.cols ||
      water.grid.spacing != scene_.grid.spacing)
    throw InputError("new constraints must keep the grid");
  WaterState state = solver_->read_state();
  const std::int64_t steps = solver_->steps_done();
  const Physics physics = scene_.physics;
  static_cast<WaterSpec&>(scene_) = water;
  scene_.physics = physics;
  WaterModel model = build();
  constrain(state, model);
  replace_solver(std::move(model), state, steps);
}

void Session::set_solver(SolverChoice choice) {
  const WaterState state = solver_->read_state();
  const std::int64_t steps = solver_->steps_done();
  const SolverChoice previous = choice_;
  choice_ = choice;
  try {
    replace_solver(build(), state, steps);
  } catch (...) {
    choice_ = previous;
    if (!solver_) replace_solver(build(), state, steps);
    throw;
  }
}

void Session::reset() {
  if (scene_.wind.ripples) ripples_until_ = kRippleHorizonSteps;
  replace_solver(build(), rest_state(solver_->model()), 0);
}

void Session::set_state(const WaterState& state, std::int64_t steps) {
  if (state.nodes() != model().nodes())
    throw InputError("set_state: " + std::to_string(state.nodes()) + " nodes for a grid of " +
                     std::to_string(model().nodes()));
  notify_change();
  solver_->set_state(state, steps);
  ++state_revision_;
}

WaterState Session::finite_state() const {
  WaterState state = solver_->read_state();
  if (first_blown_up_node(state)) throw_blow_up(state, model(), "");
  return state;
}

}  // namespace pond::sim
