// The target's baseline wide table (SSE2 on x86, NEON on aarch64) does lane for lane what the
// scalar table does, to the bit, on the values where instruction sets differ: signed zeros, NaN and
// infinities in min, max and compares (NEON's FMIN/FMAX would order -0 below +0 and return NaN; the
// tables follow SSE2's minps/maxps), and the LOD's loads and stores of interleaved data.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "sim/wide_baseline.h"
#include "sim/wide_scalar.h"

namespace pond::sim {
namespace {

using W = WideBaseline;
using S = WideScalar;
constexpr int kLanes = W::width;
using Lanes = std::array<float, kLanes>;

const float kNaN = std::numeric_limits<float>::quiet_NaN(), kInf = std::numeric_limits<float>::infinity();
// Values whose order or sign the instruction sets treat differently, and plain ones.
const float kValues[] = {0.0f, -0.0f, kNaN, -kNaN, kInf, -kInf, 1.5f, -1.5f, 1e-40f, -2.0f};
constexpr int kCount = sizeof(kValues) / sizeof(kValues[0]);

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }
Lanes lanes(W::F v) {
  Lanes out;
  W::store(out.data(), v);
  return out;
}
W::F mask_vector(W::M m) { return W::select(m, W::set1(1.0f), W::set1(0.0f)); }

// Every pair (a, b) of kValues, kLanes pairs a vector: op on the table equals op on scalars.
template <class Wide, class Scalar>
void expect_pairwise(const char* name, Wide wide, Scalar scalar) {
  std::vector<float> a, b;
  for (float x : kValues)
    for (float y : kValues) a.push_back(x), b.push_back(y);
  while (a.size() % kLanes) a.push_back(0), b.push_back(0);
  for (std::size_t i = 0; i < a.size(); i += kLanes) {
    const Lanes got = lanes(wide(W::load(&a[i]), W::load(&b[i])));
    for (int k = 0; k < kLanes; ++k)
      EXPECT_EQ(bits(got[k]), bits(scalar(a[i + k], b[i + k]))) << name << "(" << a[i + k] << ", " << b[i + k] << ")";
  }
}

TEST(WideTable, MinMaxAndComparesFollowTheScalarRules) {
  expect_pairwise("min_of", W::min_of, S::min_of);
  expect_pairwise("max_of", W::max_of, S::max_of);
  expect_pairwise("max_abs", W::max_abs, S::max_abs);
  const auto as_float = [](std::uint32_t m) { return m ? 1.0f : 0.0f; };
  expect_pairwise("less", [](W::F a, W::F b) { return mask_vector(W::less(a, b)); },
                  [&](float a, float b) { return as_float(S::less(a, b)); });
  expect_pairwise("greater", [](W::F a, W::F b) { return mask_vector(W::greater(a, b)); },
                  [&](float a, float b) { return as_float(S::greater(a, b)); });
  expect_pairwise("unordered", [](W::F a, W::F b) { return mask_vector(W::unordered(a, b)); },
                  [&](float a, float b) { return as_float(S::unordered(a, b)); });
  expect_pairwise("keep(greater)", [](W::F a, W::F b) { return W::keep(W::greater(a, b), a); },
                  [](float a, float b) { return S::keep(S::greater(a, b), a); });
  expect_pairwise("bit_or", W::bit_or, S::bit_or);
  expect_pairwise("add", W::add, S::add);
  expect_pairwise("sub", W::sub, S::sub);
  expect_pairwise("mul", W::mul, S::mul);
}

TEST(WideTable, UnaryOperationsKeepEveryBit) {
  for (int i = 0; i < kCount; ++i) {
    const float v = kValues[i];
    EXPECT_EQ(bits(lanes(W::neg(W::set1(v)))[0]), bits(S::neg(v))) << v;
    EXPECT_EQ(bits(lanes(W::abs(W::set1(v)))[0]), bits(S::abs(v))) << v;
    if (!(v < 0)) {
      EXPECT_EQ(bits(lanes(W::sqrt(W::set1(v)))[0]), bits(S::sqrt(v))) << v;
    }
    EXPECT_EQ(bits(lanes(W::rsqrt_seed(W::set1(v), 0x5f3759dfu))[0]), bits(S::rsqrt_seed(v, 0x5f3759dfu))) << v;
  }
  const Lanes iota = lanes(W::iota());
  for (int k = 0; k < kLanes; ++k) EXPECT_EQ(iota[k], float(k));
}

TEST(WideTable, MasksSetTheirLanes) {
  for (unsigned pattern = 0; pattern < (1u << kLanes); ++pattern) {
    std::uint32_t m[kLanes];
    std::uint8_t kinds[kLanes];
    for (int k = 0; k < kLanes; ++k) m[k] = (pattern >> k & 1) ? ~0u : 0u, kinds[k] = (pattern >> k & 1) ? 0 : 2;
    const W::M mask = W::load_mask(m);
    EXPECT_EQ(W::lanes_set(mask), pattern);
    EXPECT_EQ(W::any(mask), pattern != 0);
    EXPECT_EQ(W::lanes_set(W::kind_below(kinds, 1)), pattern);
    EXPECT_EQ(W::lanes_set(W::either(mask, W::none())), pattern);
    EXPECT_EQ(W::lanes_set(W::both(mask, W::load_mask(m))), pattern);
  }
  EXPECT_FALSE(W::any(W::none()));
}

TEST(WideTable, InterleavedLoadsAndStoresReadAndWriteTheirFloatsOnly) {
  std::vector<float> data(8 * kLanes + 8);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = float(i);
  W::F even, odd, first, second, x, y, z;
  W::load_evens_odds(data.data() + 1, even, odd);
  W::load_pairs(data.data() + 1, first, second);
  W::load_records(data.data() + 1, 6, x, y, z);
  for (int k = 0; k < kLanes; ++k) {
    EXPECT_EQ(lanes(even)[k], data[1 + 2 * k]);
    EXPECT_EQ(lanes(odd)[k], data[2 + 2 * k]);
    EXPECT_EQ(lanes(first)[k], data[1 + 4 * k]);
    EXPECT_EQ(lanes(second)[k], data[2 + 4 * k]);
    EXPECT_EQ(lanes(x)[k], data[1 + 6 * k]);
    EXPECT_EQ(lanes(y)[k], data[2 + 6 * k]);
    EXPECT_EQ(lanes(z)[k], data[3 + 6 * k]);
  }
  std::vector<float> out(4 * kLanes, -1.0f);
  W::store_pairs(out.data(), W::iota(), W::add(W::iota(), W::set1(100.0f)));
  for (int i = 0; i < 4 * kLanes; ++i)
    EXPECT_EQ(out[i], i % 4 == 0 ? float(i / 4) : i % 4 == 1 ? float(i / 4 + 100) : -1.0f) << i;
}

}  // namespace
}  // namespace pond::sim
