#include "tree/wind.h"

#include <algorithm>
#include <numbers>
#include <string>

#include "core/errors.h"

namespace pond::tree {

UserWind user_wind(const WindSpec& spec) {
  UserWind u;
  u.strength = static_cast<float>(spec.strength);
  u.direction = static_cast<float>(spec.direction_deg * std::numbers::pi / 180.0);
  return u;
}

Wind::Wind(const WindSpec& spec, std::size_t instances)
    : spec_(spec), user_(user_wind(spec)), noise_(make_noise_table(spec.seed)), states_(instances) {
  for (std::size_t k = 0; k < instances; ++k) states_[k].phase = instance_phase(static_cast<int>(k));
}

void Wind::advance(double seconds) {
  if (!(seconds > 0.0)) return;
  for (WindState& s : states_) advance_wind(s, noise_, user_, seconds);
  time_ += seconds;
}

void Wind::set_direction(double radians) {
  user_.direction = static_cast<float>(radians);
  spec_.direction_deg = radians * 180.0 / std::numbers::pi;
}

void Wind::set_strength(double strength) {
  const double s = std::clamp(strength, 0.0, static_cast<double>(kMaxWindStrength));
  user_.strength = static_cast<float>(s);
  spec_.strength = s;
}

void Wind::restore(const Image& image) {
  if (image.states.size() != states_.size())
    throw InternalError("Wind::restore: " + std::to_string(image.states.size()) + " instances for " +
                        std::to_string(states_.size()));
  user_ = image.user;
  spec_.strength = image.strength;
  spec_.direction_deg = image.direction_deg;
  time_ = image.time;
  states_ = image.states;
}

TreeWindFrame Wind::frame(std::size_t k, BendMode mode) const {
  const WindState calm{};
  return wind_frame(states_.empty() ? calm : states_[std::min(k, states_.size() - 1)], noise_, user_, mode);
}

}  // namespace pond::tree
