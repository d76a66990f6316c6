#include "app/demo/scene_modes.h"

#include <algorithm>

namespace pond::app::demo {

SceneModes modes_of(const scene::Scene& scene) {
  const bool islands = std::any_of(scene.constraints.begin(), scene.constraints.end(),
                                   [](const sim::ConstraintRect& c) { return c.kind == sim::NodeKind::fixed; });
  return SceneModes{.border = scene.border, .all_vertical = false, .islands = islands};
}

scene::Scene apply_modes(const scene::Scene& base, const SceneModes& modes) {
  scene::Scene s = base;
  s.border = modes.border;
  const auto is_island = [](const sim::ConstraintRect& c) { return c.kind == sim::NodeKind::fixed; };
  const bool has_islands = std::any_of(base.constraints.begin(), base.constraints.end(), is_island);
  if (!modes.islands) {
    std::erase_if(s.constraints, is_island);
  } else if (!has_islands) {
    // A square island of about a tenth of the pond, a little off centre so waves wrap around it.
    const int rows = base.grid.rows, cols = base.grid.cols;
    const int half_r = std::max(1, rows / 20), half_c = std::max(1, cols / 20);
    const int r = rows / 2 + rows / 10, c = cols / 2 - cols / 10;
    s.constraints.push_back({.kind = sim::NodeKind::fixed, .row0 = std::max(1, r - half_r),
                             .row1 = std::min(rows - 2, r + half_r), .col0 = std::max(1, c - half_c),
                             .col1 = std::min(cols - 2, c + half_c)});
  }
  if (modes.all_vertical)  // fixed still wins over vertical where both apply
    s.constraints.push_back({.kind = sim::NodeKind::vertical, .row0 = 0, .row1 = base.grid.rows - 1,
                             .col0 = 0, .col1 = base.grid.cols - 1});
  return s;
}

const char* border_name(sim::NodeKind kind) {
  switch (kind) {
    case sim::NodeKind::fixed: return "fixed";
    case sim::NodeKind::vertical: return "vertical";
    case sim::NodeKind::free: return "free";
  }
  return "?";
}

sim::NodeKind next_border(sim::NodeKind kind) {
  switch (kind) {
    case sim::NodeKind::fixed: return sim::NodeKind::vertical;
    case sim::NodeKind::vertical: return sim::NodeKind::free;
    case sim::NodeKind::free: return sim::NodeKind::fixed;
  }
  return sim::NodeKind::fixed;
}

}  // namespace pond::app::demo
