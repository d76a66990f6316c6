#include "sim/perturbation.h"

namespace pond::sim {

void apply_perturbation(const PerturbationTable& t, WaterState& s) {
  float* target = t.target == PerturbTarget::velocity ? s.vy.data() : s.uy.data();
  for (std::size_t k = 0; k < t.nodes.size(); ++k) {
    float& value = target[t.nodes[k]];
    value = t.mode == PerturbMode::add ? value + t.weights[k] : t.weights[k];
  }
}

}  // namespace pond::sim
