#pragma once
// The article's 1-D gust noise: a 256-entry table filled by midpoint displacement, sampled with
// linear interpolation and wrapping at 256 (so it is periodic: noise(s + 256) == noise(s)).
#include <array>
#include <cstdint>

namespace pond::tree {

inline constexpr int kNoiseSize = 256;
inline constexpr int kNoiseCoarsestStep = 32;

struct NoiseTable {
  std::array<float, kNoiseSize> values{};
};

// For dn = 32, 16, ..., 1 and n = dn, 3dn, 5dn, ... < 256:
//   noise[n] = (noise[n - dn] + noise[(n + dn) & 255]) / 2 + (rand - 0.5) * dn / 16.
// As in the article the table starts all zero and the coarsest step is 32, so the entries at
// multiples of 64 stay zero (the gusts return to the mean wind every 64 samples) and |noise| < 2.
NoiseTable make_noise_table(std::uint64_t seed);

// Linear interpolation between entries floor(s) and floor(s) + 1, both wrapped to 0..255. `s` is a
// double because callers pass time * rate, which outgrows a float's fraction within hours.
float sample_noise(const NoiseTable& table, double s);

}  // namespace pond::tree
