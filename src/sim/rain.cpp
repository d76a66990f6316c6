#include "sim/rain.h"

#include <sstream>

#include "core/errors.h"

namespace pond::sim {

std::vector<Perturbation> Rain::drops(const WaterModel& model, double drops_per_frame, double radius, double amplitude) {
  std::uniform_real_distribution<double> row(1, model.rows - 2), col(1, model.cols - 2), scale(0.5, 1.5);
  std::vector<Perturbation> out;
  carry_ += drops_per_frame;
  for (; carry_ >= 1; carry_ -= 1)  // a braced list: row, col, then scale drawn in this order
    out.push_back(Perturbation{.row = row(rng_), .col = col(rng_), .radius = radius, .amplitude = amplitude * scale(rng_)});
  return out;
}

Rain::Image Rain::image() const {
  std::ostringstream text;
  text << rng_;
  return {text.str(), carry_};
}

void Rain::restore(const Image& image) {
  std::istringstream text(image.engine);
  std::mt19937 rng;
  text >> rng;
  if (!text || !(image.carry >= 0 && image.carry < 1)) throw InputError("the rain's state is not valid");
  rng_ = rng;
  carry_ = image.carry;
}

}  // namespace pond::sim
