#include "sim/session.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "core/errors.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"
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

template <class F>
auto Session::guarded(F&& read) {
  try {
    return read();
  } catch (const GpuFailure& failure) {
    if (!choice_.gpu) throw;
    fail_over(failure);
    return read();
  }
}

Session::Session(SessionSpec spec, SolverChoice choice, GpuSolverFactory gpu)
    : water_(std::move(spec.water)), wind_spec_(spec.wind), rules_(std::move(spec.rules)), choice_(choice),
      gpu_(std::move(gpu)), wind_(spec.wind, spec.trees), sun_(spec.sun), notify_(std::move(spec.notify)) {
  if (wind_spec_.ripples) ripples_until_ = kRippleHorizonSteps;
  WaterModel model = build();
  const WaterState rest = rest_state(model);
  replace_solver(std::move(model), rest, 0);
}

Session::~Session() = default;

WaterModel Session::build() const {
  WaterSpec water = water_;
  add_wind_ripples(water, wind_spec_, ripples_until_);
  return build_model(water, choice_.math);
}

void Session::replace_solver(WaterModel model, const WaterState& state, std::int64_t steps) {
  if (state.nodes() != model.nodes())
    throw InternalError("the state has " + std::to_string(state.nodes()) + " nodes, the grid " +
                     std::to_string(model.nodes()));
  std::unique_ptr<Solver> next;
  if (choice_.gpu) {
    if (!gpu_) throw InternalError("a GPU solver was chosen without a factory for it");
    solver_.reset();  // one solver's buffers at a time
    try {
      next = gpu_(model);
      next->track_tile_bounds(track_tiles_);
      next->set_state(state, steps);
    } catch (const GpuFailure& failure) {  // the state is the host's: the CPU takes it as it is
      next.reset();
      choose_cpu(failure);
    }
  }
  if (!next) {
    next = std::make_unique<CpuSolver>(std::move(model), choice_.backend, choice_.threads);
    next->track_tile_bounds(track_tiles_);
    next->set_state(state, steps);
  }
  if (choice_.gpu) journal_.restart(steps, next->model().bodies);
  solver_ = std::move(next);
  ++solver_generation_;
  ++state_revision_;
}

void Session::fail_over(const GpuFailure& failure) {
  const HostSnapshot* copy = solver_->host_snapshot();
  if (!copy) throw failure;  // nothing to go on from (a solver that cannot fail has no copy)
  const HostSnapshot from = *copy;
  const std::int64_t lost_at = solver_->steps_done();
  choice_.gpu = false;
  choice_.backend = best_backend();
  solver_.reset();  // the failed solver's buffers go first
  auto cpu = std::make_unique<CpuSolver>(build(), choice_.backend, choice_.threads);
  cpu->track_tile_bounds(track_tiles_);
  cpu->set_state(from.state, from.step);
  journal_.replay(*cpu, from.step);
  solver_ = std::move(cpu);
  journal_ = SolverJournal{};
  ++solver_generation_;
  ++state_revision_;
  if (notify_)
    notify_(std::string(failure.what()) + " at step " + std::to_string(lost_at) + "; going on on the CPU (" +
            solver_->engine() + ") from the host's copy of step " + std::to_string(from.step) +
            (choice_.math == MathMode::exact ? ", with the same bits" : ""));
}

void Session::choose_cpu(const GpuFailure& failure) {
  choice_.gpu = false;
  choice_.backend = best_backend();
  if (notify_) notify_(std::string(failure.what()) + "; going on on the CPU (" + backend_name(choice_.backend) + ")");
}

void Session::recover(const GpuFailure& failure) {
  if (choice_.gpu) fail_over(failure);
}

void Session::track_tile_bounds(bool on) {
  track_tiles_ = on;
  guarded([&] { solver_->track_tile_bounds(on); });
}

void Session::trim_journal() {
  if (!journaling()) return;
  if (const HostSnapshot* copy = solver_->host_snapshot()) journal_.trim(copy->step);
}

void Session::advance(std::int64_t steps) {
  if (steps <= 0) {
    guarded([&] { solver_->advance(0); });  // the splashes, submitted
    return;
  }
  const std::int64_t end = solver_->steps_done() + steps;
  if (wind_spec_.ripples && end > ripples_until_) {
    ripples_until_ = end + kRippleHorizonSteps;
    const WaterState state = guarded([&] { return solver_->read_state(); });
    replace_solver(build(), state, solver_->steps_done());
  }
  if (journaling()) journal_.advance(solver_->steps_done(), steps);
  try {
    solver_->advance(steps);
  } catch (const GpuFailure& failure) {
    if (!choice_.gpu) throw;
    fail_over(failure);  // the journal has these steps: the CPU replays them
  }
  trim_journal();
  ++state_revision_;
}

void Session::splash(const Perturbation& splash) {
  PerturbationTable table = tabulate(splash, solver_->model());
  if (journaling()) journal_.splash(solver_->steps_done(), table);
  solver_->perturb(table);
  ++state_revision_;
}

void Session::set_physics(const Physics& physics) {
  if (rules_.physics) rules_.physics(physics, water_);
  const WaterState state = this->state();
  const std::int64_t steps = solver_->steps_done();
  water_.physics = physics;
  replace_solver(build(), state, steps);
}

void Session::set_water(const WaterSpec& water) {
  if (water.grid.rows != water_.grid.rows || water.grid.cols != water_.grid.cols ||
      water.grid.spacing != water_.grid.spacing)
    throw InternalError("new constraints must keep the grid");
  WaterState state = this->state();
  const std::int64_t steps = solver_->steps_done();
  const Physics physics = water_.physics;
  water_ = water;
  water_.physics = physics;
  WaterModel model = build();
  constrain(state, model);
  replace_solver(std::move(model), state, steps);
}

void Session::set_solver(SolverChoice choice) {
  const WaterState state = this->state();
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

void Session::set_gpu_factory(GpuSolverFactory gpu) {
  if (choice_.gpu) throw InternalError("set_gpu_factory while a GPU solver runs");
  gpu_ = std::move(gpu);
}

void Session::add_body(const BodySpec& body) {
  WaterState state = this->state();
  std::vector<std::array<double, 3>> at;  // where the bodies are now, not where the scene started them
  const double h = water_.grid.spacing;
  for (const BodyState& b : state.bodies) at.push_back({b.x * h, b.y * h, b.z * h});
  if (rules_.body) rules_.body(body, water_, model().kinds, at);
  const std::int64_t steps = solver_->steps_done();
  water_.bodies.push_back(body);
  held_.resize(water_.bodies.size());
  WaterModel model = build();
  state.bodies.push_back(model.bodies.back().initial);
  replace_solver(std::move(model), state, steps);
}

void Session::remove_body(std::size_t index) {
  if (index >= water_.bodies.size()) throw InternalError("no body " + std::to_string(index));
  WaterState state = this->state();
  const std::int64_t steps = solver_->steps_done();
  water_.bodies.erase(water_.bodies.begin() + static_cast<std::ptrdiff_t>(index));
  state.bodies.erase(state.bodies.begin() + static_cast<std::ptrdiff_t>(index));
  held_.resize(water_.bodies.size() + 1);
  held_.erase(held_.begin() + static_cast<std::ptrdiff_t>(index));
  const std::uint64_t below = (std::uint64_t{1} << index) - 1;  // index < 64
  clamp_reported_ = (clamp_reported_ & below) | ((clamp_reported_ >> 1) & ~below);
  replace_solver(build(), state, steps);
}

// A new set of body models for the solver, journaled (the GPU solver uploads them).
void Session::drag_body(std::size_t index, const std::array<double, 3>& target, std::int64_t steps) {
  if (index >= water_.bodies.size()) throw InternalError("no body " + std::to_string(index));
  held_.resize(water_.bodies.size());
  const double h = water_.grid.spacing;
  const BodyState now = bodies()[index];
  BodySpec& spec = water_.bodies[index];
  if (!held_[index]) held_[index] = spec;
  const std::array<double, 3> to{std::clamp(target[0], 0.0, (water_.grid.cols - 1) * h), target[1],
                                 std::clamp(target[2], 0.0, (water_.grid.rows - 1) * h)};
  const std::int64_t from = solver_->steps_done();
  // No faster than a body may move (shared/bodies.h): a quick drag takes more steps.
  const std::array<double, 3> d{to[0] - now.x * h, to[1] - now.y * h, to[2] - now.z * h};
  const double spacings = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / h;
  steps = std::max({steps, std::int64_t{1}, static_cast<std::int64_t>(std::ceil(spacings / POND_MAX_SPACINGS_PER_STEP))});
  spec.motion = BodyMotion::kinematic;
  spec.path = {PathKey{from, {now.x * h, now.y * h, now.z * h}}, PathKey{from + steps, to}};
  std::vector<BodyModel> models = build_bodies(water_.bodies, water_.physics, h);
  if (journaling()) journal_.body_models(from, models);
  try {
    solver_->set_body_models(std::move(models));
  } catch (const GpuFailure& failure) {
    if (!choice_.gpu) throw;
    fail_over(failure);  // the journal has the new models
  }
}

void Session::release_body(std::size_t index, const std::array<double, 3>& velocity) {
  if (!held(index)) return;
  const double h = water_.grid.spacing;
  WaterState state = this->state();
  BodyState& now = state.bodies[index];
  BodySpec spec = *held_[index];
  held_[index].reset();
  if (spec.motion == BodyMotion::floating) {
    // A throw faster than a body may move is clamped (and flagged, so the front end says so).
    const double fastest = POND_MAX_SPACINGS_PER_STEP * h / water_.physics.dt;
    const double speed = std::sqrt(velocity[0] * velocity[0] + velocity[1] * velocity[1] + velocity[2] * velocity[2]);
    const double scale = speed > fastest ? fastest / speed : 1.0;
    if (speed > fastest) now.flags |= shared::kBodyClamped;
    spec.position = {now.x * h, now.y * h, now.z * h};
    spec.velocity = {velocity[0] * scale, velocity[1] * scale, velocity[2] * scale};
    now.vx = static_cast<float>(spec.velocity[0] / h);
    now.vy = static_cast<float>(spec.velocity[1] / h);
    now.vz = static_cast<float>(spec.velocity[2] / h);
  } else {
    spec.path = {PathKey{solver_->steps_done(), {now.x * h, now.y * h, now.z * h}}};
    now.vx = now.vy = now.vz = 0.0f;
  }
  water_.bodies[index] = spec;
  put_state(state, solver_->steps_done(), build_bodies(water_.bodies, water_.physics, h));
}

void Session::reset() {
  clamp_reported_ = 0;
  for (std::size_t b = 0; b < held_.size(); ++b)  // held bodies go back to their own motion
    if (held_[b]) water_.bodies[b] = *held_[b];
  held_.assign(water_.bodies.size(), std::nullopt);
  if (wind_spec_.ripples) ripples_until_ = kRippleHorizonSteps;
  WaterModel model = build();
  const WaterState rest = rest_state(model);
  replace_solver(std::move(model), rest, 0);
}

void Session::set_state(const WaterState& state, std::int64_t steps) {
  if (state.nodes() != model().nodes())
    throw InternalError("set_state: " + std::to_string(state.nodes()) + " nodes for a grid of " +
                     std::to_string(model().nodes()));
  put_state(state, steps, {});
}

// The same solver with new body models (unless empty) and a new state: the host holds it, so the
// journal starts again from it.
void Session::put_state(const WaterState& state, std::int64_t steps, std::vector<BodyModel> bodies) {
  try {
    if (!bodies.empty()) solver_->set_body_models(std::move(bodies));
    solver_->set_state(state, steps);
  } catch (const GpuFailure& failure) {
    if (!choice_.gpu) throw;
    choose_cpu(failure);
    replace_solver(build(), state, steps);
    return;
  }
  if (journaling()) journal_.restart(steps, solver_->model().bodies);
  ++state_revision_;
}

WaterState Session::state() {
  return guarded([&] { return solver_->read_state(); });
}

std::vector<BodyState> Session::bodies() {
  return guarded([&] { return solver_->read_bodies(); });
}

WaterState Session::finite_state() {
  WaterState state = this->state();
  if (first_blown_up_node(state) || first_blown_up_body(state)) throw_blow_up(state, model(), "");
  return state;
}

std::string Session::clamp_notice(const std::vector<BodyState>& bodies) {
  std::string list;
  for (std::size_t b = 0; b < bodies.size() && b < 64; ++b)
    if ((bodies[b].flags & shared::kBodyClamped) != 0u && !(clamp_reported_ >> b & 1u)) {
      clamp_reported_ |= std::uint64_t{1} << b;
      list += (list.empty() ? "" : ", ") + std::to_string(b);
    }
  if (list.empty()) return {};
  char limit[32];
  std::snprintf(limit, sizeof limit, "%g", POND_MAX_SPACINGS_PER_STEP);
  return "body " + list + " moved faster than " + limit + " grid spacings a step; its speed was clamped";
}

}  // namespace pond::sim
