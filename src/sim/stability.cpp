#include "sim/stability.h"

#include <cmath>
#include <limits>

namespace pond::sim {

double stability_bound(double mass, double stiffness, double damping) {
  const double b = damping / mass;
  const double w2 = 8.0 * stiffness / mass;
  if (w2 <= 0.0) return b > 0.0 ? 2.0 / b : std::numeric_limits<double>::infinity();
  const double bound = (std::sqrt(b * b + 4.0 * w2) - b) / w2;
  // Damping alone also needs b dt < 2.
  return b > 0.0 ? std::fmin(bound, 2.0 / b) : bound;
}

}  // namespace pond::sim
