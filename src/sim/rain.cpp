#include "sim/rain.h"

namespace pond::sim {

std::vector<Perturbation> Rain::drops(const WaterModel& model, double drops_per_frame, double radius, double amplitude) {
  std::uniform_real_distribution<double> row(1, model.rows - 2), col(1, model.cols - 2), scale(0.5, 1.5);
  std::vector<Perturbation> out;
  carry_ += drops_per_frame;
  for (; carry_ >= 1; carry_ -= 1)  // a braced list: row, col, then scale drawn in this order
    out.push_back(Perturbation{.row = row(rng_), .col = col(rng_), .radius = radius, .amplitude = amplitude * scale(rng_)});
  return out;
}

}  // namespace pond::sim
