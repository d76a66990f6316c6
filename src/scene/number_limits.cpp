#include "scene/number_limits.h"

#include "core/text.h"

namespace pond::scene {

std::optional<std::string> outside(double value, double lo, double hi, const std::string& unit) {
  if (value >= lo && value <= hi) return std::nullopt;
  return "is " + number_outside(value, lo, hi) + ", outside [" + number_text(lo) + ", " + number_text(hi) + "]" + unit;
}

}  // namespace pond::scene
