#include "sim/perturbation.h"

#include <algorithm>

namespace pond::sim {

void apply_perturbation(const PerturbationTable& t, WaterState& s) {
  float* target = t.target == PerturbTarget::velocity ? s.vy.data() : s.uy.data();
  for (std::size_t k = 0; k < t.nodes.size(); ++k) {
    float& value = target[t.nodes[k]];
    value = t.mode == PerturbMode::add ? value + t.weights[k] : t.weights[k];
  }
}

NodeRect node_rect(const PerturbationTable& t, int cols) {
  const auto c = static_cast<std::uint32_t>(cols);
  NodeRect r{static_cast<int>(t.nodes[0] / c), static_cast<int>(t.nodes[0] / c), static_cast<int>(t.nodes[0] % c),
             static_cast<int>(t.nodes[0] % c)};
  for (std::uint32_t n : t.nodes) {
    const int i = static_cast<int>(n / c), j = static_cast<int>(n % c);
    r = {std::min(r.row0, i), std::max(r.row1, i), std::min(r.col0, j), std::max(r.col1, j)};
  }
  return r;
}

}  // namespace pond::sim
