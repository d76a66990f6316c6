#pragma once
// What a session did to its solver since the newest state the host holds a copy of: the steps, the
// splashes and the bodies' models, each at the step it was given. When a GPU solver fails (its
// device lost, its memory short: core/errors.h GpuFailure), a CPU solver starts from that copy and
// replays the journal, and so reaches the bits the GPU would have (docs/gpu.md, the CPU twin).
#include <cstdint>
#include <vector>

#include "sim/model.h"
#include "sim/solver.h"

namespace pond::sim {

class SolverJournal {
 public:
  // A solver starts at `step` with `bodies` as its bodies' models: nothing before it is needed.
  void restart(std::int64_t step, std::vector<BodyModel> bodies);
  void advance(std::int64_t from, std::int64_t steps);
  void splash(std::int64_t at, PerturbationTable table);
  void body_models(std::int64_t at, std::vector<BodyModel> bodies);
  // Forgets what the host's copy at `step` already holds.
  void trim(std::int64_t step);
  // Replays onto `solver`, whose state is the host's copy at `step` (at or after the restart), what
  // came after it.
  void replay(Solver& solver, std::int64_t step) const;
  std::size_t entries() const { return entries_.size(); }

 private:
  enum class Kind { advance, splash, bodies };
  struct Entry {
    Kind kind;
    std::int64_t step;    // when it was given: steps_done() then
    std::int64_t steps;   // advance: how many
    PerturbationTable table;        // splash
    std::vector<BodyModel> bodies;  // bodies
  };
  std::vector<BodyModel> base_;  // the bodies' models before the first entry
  std::vector<Entry> entries_;
};

}  // namespace pond::sim
