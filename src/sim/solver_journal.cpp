#include "sim/solver_journal.h"

#include <algorithm>
#include <utility>

namespace pond::sim {

void SolverJournal::restart(std::int64_t, std::vector<BodyModel> bodies) {
  base_ = std::move(bodies);
  entries_.clear();
}

void SolverJournal::advance(std::int64_t from, std::int64_t steps) {
  if (steps <= 0) return;
  if (!entries_.empty() && entries_.back().kind == Kind::advance &&
      entries_.back().step + entries_.back().steps == from) {
    entries_.back().steps += steps;  // one entry for a run of steps with nothing between them
    return;
  }
  entries_.push_back({Kind::advance, from, steps, {}, {}});
}

void SolverJournal::splash(std::int64_t at, PerturbationTable table) {
  entries_.push_back({Kind::splash, at, 0, std::move(table), {}});
}

void SolverJournal::body_models(std::int64_t at, std::vector<BodyModel> bodies) {
  entries_.push_back({Kind::bodies, at, 0, {}, std::move(bodies)});
}

// A splash or a change of models given at step s acts on the steps from s on; a copy at step s is
// taken at the end of the steps before s, before anything given at s (the GPU solver copies at the
// end of a submission's steps; what is given afterwards goes into a later submission).
void SolverJournal::trim(std::int64_t step) {
  std::size_t keep = 0;
  while (keep < entries_.size()) {
    Entry& e = entries_[keep];
    const std::int64_t end = e.kind == Kind::advance ? e.step + e.steps : e.step + 1;
    if (end > step) break;
    if (e.kind == Kind::bodies) base_ = std::move(e.bodies);
    ++keep;
  }
  entries_.erase(entries_.begin(), entries_.begin() + static_cast<std::ptrdiff_t>(keep));
}

void SolverJournal::replay(Solver& solver, std::int64_t step) const {
  const std::vector<BodyModel>* models = &base_;
  for (const Entry& e : entries_)
    if (e.kind == Kind::bodies && e.step < step) models = &e.bodies;
  if (!models->empty()) solver.set_body_models(*models);
  for (const Entry& e : entries_) {
    switch (e.kind) {
      case Kind::advance:
        if (e.step + e.steps > step) solver.advance(e.step + e.steps - std::max(e.step, step));
        break;
      case Kind::splash:
        if (e.step >= step) solver.perturb(e.table);
        break;
      case Kind::bodies:
        if (e.step >= step) solver.set_body_models(e.bodies);
        break;
    }
  }
}

}  // namespace pond::sim
