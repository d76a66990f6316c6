#include "sim/exact_exp.h"

#include <cmath>

namespace pond::sim {

double exact_exp(double x) {
  if (x < -745.0) return 0.0;
  if (x > 709.0) return HUGE_VAL;
  // x = k ln2 + r with |r| <= ln2/2; ln2 split in a high part with trailing zero bits (so k*hi is
  // exact) and a low part.
  constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  constexpr double inv_ln2 = 1.44269504088896338700e+00;
  const double kd = std::nearbyint(x * inv_ln2);
  const double r = (x - kd * ln2_hi) - kd * ln2_lo;
  // Taylor series to degree 14: |r|^15/15! < 2e-15 relative for |r| <= 0.347.
  double p = 1.0 / 87178291200.0;  // 1/14!
  constexpr double inv_fact[] = {1.0 / 6227020800.0, 1.0 / 479001600.0, 1.0 / 39916800.0,
                                 1.0 / 3628800.0,    1.0 / 362880.0,    1.0 / 40320.0,
                                 1.0 / 5040.0,       1.0 / 720.0,       1.0 / 120.0,
                                 1.0 / 24.0,         1.0 / 6.0,         0.5,
                                 1.0,                1.0};
  for (double c : inv_fact) p = p * r + c;
  return std::ldexp(p, static_cast<int>(kd));
}

}  // namespace pond::sim
