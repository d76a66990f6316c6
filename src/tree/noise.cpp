#include "tree/noise.h"

#include <cmath>

#include "tree/pcg32.h"

namespace pond::tree {

NoiseTable make_noise_table(std::uint64_t seed) {
  Pcg32 rng(seed, RandomStream::noise);
  NoiseTable t;
  auto& v = t.values;
  for (int dn = kNoiseCoarsestStep; dn >= 1; dn /= 2) {
    const float amplitude = static_cast<float>(dn) / 16.0f;
    for (int n = dn; n < kNoiseSize; n += 2 * dn) {
      const float mid = (v[static_cast<std::size_t>(n - dn)] +
                         v[static_cast<std::size_t>((n + dn) & (kNoiseSize - 1))]) * 0.5f;
      v[static_cast<std::size_t>(n)] = mid + (rng.uniform() - 0.5f) * amplitude;
    }
  }
  return t;
}

float sample_noise(const NoiseTable& table, double s) {
  // The table's period is 256, so reduce first: fmod is exact, keeps the integer conversion below in
  // range for any time, and wraps negative arguments the way the article's `And 255` does.
  double m = std::isfinite(s) ? std::fmod(s, static_cast<double>(kNoiseSize)) : 0.0;
  if (m < 0.0) m += kNoiseSize;
  const double cell = std::floor(m);
  const auto frac = static_cast<float>(m - cell);
  const auto n1 = static_cast<std::uint32_t>(cell) & (kNoiseSize - 1);  // m + 256 may round to 256
  const std::uint32_t n2 = (n1 + 1u) & (kNoiseSize - 1);
  return table.values[n1] * (1.0f - frac) + table.values[n2] * frac;
}

}  // namespace pond::tree
