// Fuzz target: the scene parser and validator (parse_scene), then, for small grids, the model built
// from it (build_model in both math modes) and a few steps of the whole session on the scalar CPU
// solver, bodies and all. The properties (issue 60): a scene is either refused with one printable
// line naming what is wrong, or it runs finite; an accepted scene that blows up within a few steps
// means a number passed validation outside the range where its arithmetic stays finite.
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

#include "core/errors.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "sim/model.h"
#include "sim/session.h"
#include "targets.h"

namespace pond::fuzz {
namespace {

constexpr std::int64_t kSteps = 4;

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
    const sim::WaterModel model = sim::build_model(s, math);
    if (model.nodes() != static_cast<std::size_t>(s.grid.rows) * static_cast<std::size_t>(s.grid.cols) ||
        model.kinds.size() != model.nodes())
      property_failed("model size differs from the scene's grid");
    for (const sim::PerturbationTable& t : model.perturbations) {
      for (std::uint32_t n : t.nodes)
        if (n >= model.nodes()) property_failed("perturbation node outside the grid");
      for (float w : t.weights)
        if (!std::isfinite(w)) property_failed("a perturbation weight that is not finite");
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
