// The exact-math building blocks: the Newton reciprocal square root, the same bits from every
// wide-float backend, and the deterministic exp behind the perturbation tables.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "shared/exact_math.h"
#include "sim/exact_exp.h"
#include "sim/step_kernel.h"
#include "sim/wide_baseline.h"

namespace pond::sim {
namespace {

TEST(ExactMath, RsqrtAccuracy) {
  double worst3 = 0, worst2 = 0;
  for (std::uint32_t bits = 0x00800000u; bits < 0x7f000000u; bits += 4099u) {
    const float x = std::bit_cast<float>(bits);
    const double truth = 1.0 / std::sqrt(double(x));
    worst3 = std::max(worst3, std::fabs(shared::rsqrt_exact(x, 3) / truth - 1));
    worst2 = std::max(worst2, std::fabs(shared::rsqrt_exact(x, 2) / truth - 1));
  }
  EXPECT_LT(worst3, 2.5e-7);  // three steps: float accuracy (measured 1.7e-7, 3 ulp)
  EXPECT_LT(worst2, 5e-6);    // two steps: the fast mode (measured 4.7e-6)
}

template <class W>
void expect_same_rsqrt_as_scalar() {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 8.0f);
  alignas(32) float in[W::width], out[W::width];
  for (int round = 0; round < 2000; ++round) {
    for (float& v : in) v = u(rng);
    W::store(out, StepKernel<W, 3>::rsqrt(W::load(in)));
    for (int k = 0; k < W::width; ++k)
      ASSERT_EQ(std::bit_cast<std::uint32_t>(out[k]),
                std::bit_cast<std::uint32_t>(shared::rsqrt_exact(in[k], 3)))
          << in[k];
  }
}

TEST(ExactMath, WideRsqrtEqualsTheSharedReference) {
  expect_same_rsqrt_as_scalar<WideScalar>();
  expect_same_rsqrt_as_scalar<WideBaseline>();  // SSE2 or NEON
}

TEST(ExactMath, SignedZeroIdentities) {
  // The kernel skips a missing neighbour by adding -0 or subtracting +0: the identity on all floats.
  for (float x : {0.0f, -0.0f, 1.0f, -3.5f, 1e-40f, -1e-40f}) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(x + -0.0f), std::bit_cast<std::uint32_t>(x));
    EXPECT_EQ(std::bit_cast<std::uint32_t>(x - 0.0f), std::bit_cast<std::uint32_t>(x));
  }
}

TEST(ExactMath, ExpMatchesLibm) {
  for (double x = -50; x <= 5; x += 0.0137) EXPECT_NEAR(exact_exp(x) / std::exp(x), 1.0, 4e-15) << x;
  EXPECT_EQ(exact_exp(0.0), 1.0);
  EXPECT_EQ(exact_exp(-800.0), 0.0);
}

}  // namespace
}  // namespace pond::sim
