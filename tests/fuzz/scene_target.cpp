// Fuzz target: the scene parser and validator (parse_scene), then, for small grids, the model built
// from it (build_model in both math modes) and two steps of the scalar CPU solver. Every rejection
// must be an InputError naming what is wrong; a model that builds must be usable.
#include <cmath>
#include <string_view>

#include "core/errors.h"
#include "sim/cpu_solver.h"
#include "sim/model.h"
#include "scene/scene.h"
#include "targets.h"

namespace pond::fuzz {

int scene(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  scene::Scene s;
  try {
    s = scene::parse_scene(text, "fuzz.json");
  } catch (const InputError& e) {
    if (std::string_view(e.what()).empty()) property_failed("InputError without a message");
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
      for (const sim::PerturbationTable& t : model.perturbations)
        for (std::uint32_t n : t.nodes)
          if (n >= model.nodes()) property_failed("perturbation node outside the grid");
      sim::CpuSolver solver(std::move(model), sim::Backend::scalar, 1);
      solver.advance(2);
    } catch (const InputError& e) {
      if (std::string_view(e.what()).empty()) property_failed("InputError without a message");
    }
  }
  return 0;
}

}  // namespace pond::fuzz
