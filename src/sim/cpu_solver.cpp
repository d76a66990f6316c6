#include "sim/cpu_solver.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.h"
#include "sim/contact.h"
#include "sim/diagnostics.h"
#include "sim/perturbation.h"

namespace pond::sim {
namespace {

// Below this many nodes per part, waking another thread costs more than it saves.
constexpr std::size_t kMinNodesPerPart = 16384;

}  // namespace

CpuSolver::CpuSolver(WaterModel model, Backend backend, int threads)
    : model_(std::move(model)),
      backend_(backend),
      kernel_(step_rows_for(backend, model_.constants.rsqrt_steps, !model_.bodies.empty(), false)),
      tile_kernel_(step_rows_for(backend, model_.constants.rsqrt_steps, !model_.bodies.empty(), true)) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::size_t by_size = std::max<std::size_t>(1, model_.nodes() / kMinNodesPerPart);
  parts_ = static_cast<int>(std::min<std::size_t>({static_cast<std::size_t>(threads), by_size,
                                                   static_cast<std::size_t>(model_.rows)}));
  threads_ = std::make_unique<RowThreads>(parts_);
  for (int p = 0; p < parts_; ++p) scratch_.emplace_back(std::size_t{kSpringRows} * kSlots);
  checks_.resize(parts_);
  reaches_.resize(parts_);
  cur_ = rest_state(model_);
  next_ = WaterState(model_.nodes());
  tile_grid_ = TileGrid(model_.rows, model_.cols);
}

std::pair<int, int> CpuSolver::part_rows(int p) const {
  return {static_cast<int>(static_cast<long long>(model_.rows) * p / parts_),
          static_cast<int>(static_cast<long long>(model_.rows) * (p + 1) / parts_)};
}

void CpuSolver::track_tile_bounds(bool on) {
  tile_columns_.clear();
  tile_rows_.clear();
  tile_spans_.clear();
  tile_bounds_.clear();
  if (!on) return;
  for (int p = 0; p < parts_; ++p) {
    const auto [r0, r1] = part_rows(p);
    tile_spans_.push_back(tile_rows_of(r0, r1, model_.rows));
    tile_rows_.emplace_back(static_cast<std::size_t>(tile_spans_.back().count()) * tile_grid_.tiles_x);
    tile_columns_.emplace_back(std::size_t{6} * kColumnsPitch);
  }
  tile_bounds_ = compute_tile_bounds(cur_, tile_grid_);
}

void CpuSolver::refresh_tiles(const NodeRect& moved) {
  if (!tile_bounds_.empty()) recompute_tiles(tile_bounds_, cur_, tile_grid_, moved);
}

void CpuSolver::set_state(const WaterState& state, std::int64_t steps_done) {
  if (state.bodies.size() != model_.bodies.size())
    throw InternalError("set_state: " + std::to_string(state.bodies.size()) + " bodies for a model of " +
                     std::to_string(model_.bodies.size()));
  cur_ = state;
  if (!tile_bounds_.empty()) tile_bounds_ = compute_tile_bounds(cur_, tile_grid_);
  step_ = steps_done;
  next_perturbation_ = 0;
  while (next_perturbation_ < model_.perturbations.size() &&
         model_.perturbations[next_perturbation_].step < step_)
    ++next_perturbation_;
}

void CpuSolver::substep(int substep_index, bool tiles) {
  const StepView v{cur_.ux.data(),  cur_.uy.data(),  cur_.uz.data(),  cur_.vx.data(),
                   cur_.vy.data(),  cur_.vz.data(),  next_.ux.data(), next_.uy.data(),
                   next_.uz.data(), next_.vx.data(), next_.vy.data(), next_.vz.data(),
                   model_.kinds.data(), model_.rows, model_.cols, model_.constants};
  const StepRowsFn kernel = tiles ? tile_kernel_ : kernel_;
  threads_->run(parts_, [&](int p) {
    const auto [r0, r1] = part_rows(p);
    TileSink sink{tiles ? tile_rows_[p].data() : nullptr, tiles ? tile_columns_[p].data() : nullptr,
                  tiles ? tile_spans_[p].first : 0};
    checks_[p] = kernel(v, r0, r1, scratch_[p].data(), &reaches_[p], &sink);
  });
  std::swap(cur_, next_);
  cur_.bodies.swap(next_.bodies);  // the bodies live in the current state only
  for (float c : checks_)
    if (!std::isfinite(c)) throw_blow_up(cur_, model_, "step " + std::to_string(step_) + ": ");
  if (tiles) {
    std::vector<const TileBounds*> parts;
    for (const auto& rows : tile_rows_) parts.push_back(rows.data());
    merge_tile_rows(tile_bounds_, tile_grid_, tile_spans_, parts);
  }
  if (!model_.bodies.empty()) {
    float reach = 0.0f;  // the largest horizontal displacement of any node
    for (float r : reaches_) reach = r > reach ? r : reach;
    moved_.clear();
    resolve_contacts(cur_, model_, step_, substep_index, reach, tiles ? &moved_ : nullptr);
    for (const NodeRect& r : moved_) refresh_tiles(r);
    if (first_blown_up_body(cur_)) throw_blow_up(cur_, model_, "step " + std::to_string(step_) + ": ");
  }
}

void CpuSolver::perturb(const PerturbationTable& table) {
  apply_perturbation(table, cur_);
  // A splash of velocities moves no node yet. (The scheduled ones in advance() need no refresh:
  // its last substep emits every tile.)
  if (table.target == PerturbTarget::position && !table.nodes.empty()) refresh_tiles(node_rect(table, model_.cols));
}

void CpuSolver::set_body_models(std::vector<BodyModel> bodies) {
  if (bodies.size() != model_.bodies.size()) throw InternalError("set_body_models: another number of bodies");
  model_.bodies = std::move(bodies);
}

std::string CpuSolver::engine() const {
  return std::string(backend_name(backend_)) + " x " + std::to_string(threads()) +
         (threads() == 1 ? " thread" : " threads");
}

void CpuSolver::advance(std::int64_t steps) {
  for (std::int64_t s = 0; s < steps; ++s) {
    while (next_perturbation_ < model_.perturbations.size() &&
           model_.perturbations[next_perturbation_].step == step_)
      apply_perturbation(model_.perturbations[next_perturbation_++], cur_);
    for (int k = 0; k < model_.substeps; ++k)
      substep(k, !tile_bounds_.empty() && s + 1 == steps && k + 1 == model_.substeps);
    ++step_;
  }
}

}  // namespace pond::sim
