// Fuzz target: the scene parser and validator (parse_scene), then, for small grids, the model built
// from it (build_model in both math modes) and a few steps of the scalar CPU solver, then of the
// whole session, bodies and all. Every rejection must be one printable line naming the file first;
// a model that builds must be the scene's and keep the spec's rules through its steps, each checked
// here from the scene, not from the model's code:
//  - the node kinds: the border kind on every border node, then the rectangles, fixed winning;
//  - each perturbation's table: exactly the nodes that are not fixed within 3 radii of its centre,
//    with the weight amplitude * exp(-d^2 / (2 r^2)) (grid units: over the spacing);
//  - after the steps: every value finite, fixed nodes at rest, vertical-only nodes without
//    horizontal displacement or velocity; and a scene with nothing to move it (no perturbation
//    before the last step, no pre-tension, no bodies) exactly at rest;
//  - the session runs finite: an accepted scene that blows up within a few steps means a number
//    passed validation outside the range where its arithmetic stays finite (issue 60).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "sim/cpu_solver.h"
#include "sim/model.h"
#include "sim/session.h"
#include "targets.h"

namespace pond::fuzz {
namespace {

constexpr std::int64_t kSteps = 4;

std::uint8_t kind(sim::NodeKind k) { return static_cast<std::uint8_t>(k); }

void check_kinds(const scene::Scene& s, const sim::WaterModel& m) {
  const int rows = s.grid.rows, cols = s.grid.cols;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      sim::NodeKind want = i == 0 || j == 0 || i == rows - 1 || j == cols - 1 ? s.border : sim::NodeKind::free;
      for (const sim::ConstraintRect& r : s.constraints)
        if (i >= r.row0 && i <= r.row1 && j >= r.col0 && j <= r.col1 && want != sim::NodeKind::fixed) want = r.kind;
      if (m.kinds[static_cast<std::size_t>(i) * cols + j] != kind(want)) property_failed("a node's kind is not the scene's");
    }
}

void check_table(const sim::Perturbation& p, const sim::PerturbationTable& t, const sim::WaterModel& m) {
  if (t.nodes.size() != t.weights.size()) property_failed("a perturbation table's nodes and weights differ in number");
  const double h = m.spacing, limit = 3 * p.radius;
  std::size_t k = 0;
  for (int i = 0; i < m.rows; ++i)
    for (int j = 0; j < m.cols; ++j) {
      const std::size_t n = static_cast<std::size_t>(i) * m.cols + j;
      const double di = (i - p.row) * h, dj = (j - p.col) * h, d = std::sqrt(di * di + dj * dj);
      const bool listed = k < t.nodes.size() && t.nodes[k] == n;
      const bool inside = m.kinds[n] != kind(sim::NodeKind::fixed) && d <= limit;
      // Nodes at the very edge of the reach may fall either way by rounding.
      if (listed != inside && std::fabs(d - limit) > 1e-9 * (1 + limit))
        property_failed(listed ? "a perturbation reaches a fixed node or one beyond 3 radii"
                               : "a perturbation misses a free node within 3 radii");
      if (!listed) continue;
      const double want = p.amplitude * std::exp(-d * d / (2 * p.radius * p.radius)) / h;
      // Relative to float rounding and the model's own exp; beyond float's range the step refuses it.
      if (std::fabs(want) < 3e38 && !(std::fabs(t.weights[k] - want) <= 1e-5 * std::fabs(want) + 1e-36))
        property_failed("a perturbation weight is not amplitude * exp(-d^2 / (2 r^2))");
      ++k;
    }
  if (k != t.nodes.size()) property_failed("a perturbation table lists nodes out of order or twice");
}

void check_state(const scene::Scene& s, const sim::WaterModel& m, const sim::WaterState& st) {
  bool still = s.physics.rest_ratio == 1.0 && s.bodies.empty();
  for (const sim::Perturbation& p : s.perturbations) still = still && p.step >= kSteps;
  for (std::size_t n = 0; n < m.nodes(); ++n) {
    const float u[6] = {st.ux[n], st.uy[n], st.uz[n], st.vx[n], st.vy[n], st.vz[n]};
    for (float x : u)
      if (!std::isfinite(x)) property_failed("a step left a non-finite value without an error");
    if (m.kinds[n] == kind(sim::NodeKind::fixed))
      for (float x : u)
        if (x != 0.0f) property_failed("a fixed node moved");
    if (m.kinds[n] == kind(sim::NodeKind::vertical) && (u[0] != 0.0f || u[2] != 0.0f || u[3] != 0.0f || u[5] != 0.0f))
      property_failed("a vertical-only node moved sideways");
    if (still)
      for (float x : u)
        if (x != 0.0f) property_failed("a pond with nothing to move it left its rest");
  }
}

// One line naming the file first, nothing a terminal would act on (core/text.h escapes user text).
void check_refusal(const InputError& e) {
  const std::string_view m = e.what();
  if (m.rfind("fuzz.json: ", 0) != 0 || m.size() == 11) property_failed("a refusal that does not name the file first");
  for (char c : m)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) property_failed("a refusal with a control byte");
}

}  // namespace

int scene(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  scene::Scene s;
  try {
    s = scene::parse_scene(text, "fuzz.json");
  } catch (const InputError& e) {
    check_refusal(e);
    return 0;
  }
  // Keep each input fast: the grid and the perturbation tables bound the work.
  if (static_cast<long long>(s.grid.rows) * s.grid.cols > 64 * 64 || s.perturbations.size() > 64) return 0;
  for (const sim::MathMode math : {sim::MathMode::exact, sim::MathMode::fast}) {
    try {
      sim::WaterModel model = sim::build_model(s, math);
      if (model.nodes() != static_cast<std::size_t>(s.grid.rows) * static_cast<std::size_t>(s.grid.cols) ||
          model.kinds.size() != model.nodes())
        property_failed("model size differs from the scene's grid");
      if (model.perturbations.size() != s.perturbations.size()) property_failed("a perturbation went missing");
      check_kinds(s, model);
      // The model keeps the scene's perturbations sorted by step, scene order within a step.
      std::vector<const sim::Perturbation*> sorted;
      for (const sim::Perturbation& p : s.perturbations) sorted.push_back(&p);
      std::stable_sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->step < b->step; });
      for (std::size_t k = 0; k < sorted.size(); ++k) check_table(*sorted[k], model.perturbations[k], model);
      const sim::WaterModel kept = model;
      sim::CpuSolver solver(std::move(model), sim::Backend::scalar, 1);
      solver.advance(kSteps);
      check_state(s, kept, solver.state());
    } catch (const InputError& e) {  // refused when built: no session to run
      if (std::string_view(e.what()).empty()) property_failed("InputError without a message");
      return 0;
    }
  }
  try {
    sim::Session session(scene::session_spec(s), sim::SolverChoice{.gpu = false, .backend = sim::Backend::scalar, .threads = 1});
    session.advance(kSteps);
    session.finite_state();  // throws "... blew up" naming no key: the property's failure below
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    property_failed("an accepted scene did not run finite for a few steps");
  }
  return 0;
}

}  // namespace pond::fuzz
