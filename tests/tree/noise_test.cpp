// The 256-entry midpoint-displacement gust noise and its sampling.
#include <gtest/gtest.h>

#include <cmath>

#include "tree/noise.h"
#include "tree/pcg32.h"

namespace pond::tree {
namespace {

// Lowest set bit of n: the step dn at which entry n was written.
int step_of(int n) { return n & -n; }

TEST(tree_noise, EntriesAtMultiplesOf64StayZero) {
  const NoiseTable t = make_noise_table(5);
  for (int n = 0; n < kNoiseSize; n += 64) EXPECT_EQ(t.values[size_t(n)], 0.0f) << "entry " << n;
}

TEST(tree_noise, EveryEntryIsTheMidpointOfItsNeighboursPlusBoundedDisplacement) {
  const NoiseTable t = make_noise_table(5);
  for (int n = 1; n < kNoiseSize; ++n) {
    if (n % 64 == 0) continue;
    const int dn = step_of(n);
    ASSERT_LE(dn, 32);
    const float mid = (t.values[size_t(n - dn)] + t.values[size_t((n + dn) & 255)]) * 0.5f;
    // (rand - 0.5) * dn / 16 with rand in [0, 1): displacement in [-dn/32, dn/32).
    const float displacement = t.values[size_t(n)] - mid;
    EXPECT_GE(displacement, -static_cast<float>(dn) / 32.0f - 1e-6f) << "entry " << n;
    EXPECT_LT(displacement, static_cast<float>(dn) / 32.0f + 1e-6f) << "entry " << n;
  }
}

// The exact construction order: coarse to fine, left to right, one draw per entry from the seed's
// noise stream. Recomputed here draw by draw.
TEST(tree_noise, ConstructionOrderRecomputedDrawByDraw) {
  const std::uint64_t seed = 77;
  const NoiseTable t = make_noise_table(seed);
  Pcg32 rng(seed, RandomStream::noise);
  float ref[256] = {};
  int draws = 0;
  for (int dn = 32; dn >= 1; dn >>= 1)
    for (int n = dn; n < 256; n += 2 * dn, ++draws)
      ref[n] = (ref[n - dn] + ref[(n + dn) & 255]) * 0.5f + (rng.uniform() - 0.5f) * float(dn) / 16.0f;
  EXPECT_EQ(draws, 4 + 8 + 16 + 32 + 64 + 128);
  for (int n = 0; n < 256; ++n) EXPECT_EQ(t.values[size_t(n)], ref[n]) << "entry " << n;
}

TEST(tree_noise, BoundedByTheSumOfDisplacements) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const NoiseTable t = make_noise_table(seed);
    for (float v : t.values) EXPECT_LT(std::abs(v), 2.0f);  // 1 + 1/2 + ... + 1/32 < 2
  }
}

TEST(tree_noise, SamplingInterpolatesLinearlyAndWrapsAt256) {
  const NoiseTable t = make_noise_table(9);
  const auto& v = t.values;
  EXPECT_EQ(sample_noise(t, 17.0), v[17]);
  EXPECT_FLOAT_EQ(sample_noise(t, 17.25), v[17] * 0.75f + v[18] * 0.25f);
  EXPECT_FLOAT_EQ(sample_noise(t, 255.5), (v[255] + v[0]) * 0.5f) << "wraps to entry 0";
  EXPECT_FLOAT_EQ(sample_noise(t, 256.0 + 3.5), sample_noise(t, 3.5)) << "period 256";
  EXPECT_FLOAT_EQ(sample_noise(t, -0.5), sample_noise(t, 255.5)) << "negative arguments wrap";
  EXPECT_FLOAT_EQ(sample_noise(t, 1e12 + 3.5), sample_noise(t, 3.5)) << "large times stay in range";
  EXPECT_EQ(sample_noise(t, std::nan("")), v[0]);
}

TEST(tree_noise, SeedsGiveDifferentTables) {
  EXPECT_NE(make_noise_table(1).values, make_noise_table(2).values);
  EXPECT_EQ(make_noise_table(3).values, make_noise_table(3).values);
}

}  // namespace
}  // namespace pond::tree
