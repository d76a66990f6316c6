#pragma once
// The tree's random generator: PCG32 (O'Neill 2014, XSH-RR output, 64-bit state), written out here
// so that a seed gives the same tree on every platform and compiler. (The distributions of <random>
// are implementation-defined, so they are never used for anything that must reproduce.)
//
// Independent parts of the tree draw from independent streams of the same seed (PCG's increment
// selects the stream), so changing how one part draws never reshuffles another.
#include <cstdint>

namespace pond::tree {

// The streams: one per consumer of randomness.
enum class RandomStream : std::uint64_t {
  skeleton = 1,  // branch directions and lengths
  jitter = 2,    // twig-jitter coefficients
  noise = 3,     // the midpoint-displacement noise table
  phase = 4,     // per-instance time offsets
};

class Pcg32 {
 public:
  Pcg32(std::uint64_t seed, RandomStream stream)
      : inc_((static_cast<std::uint64_t>(stream) << 1u) | 1u) {
    next();  // the reference seeding sequence (pcg32_srandom_r)
    state_ += seed;
    next();
  }

  std::uint32_t next() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0, 1) on the 2^24 floats k / 2^24: exact, so no rounding can ever give 1.
  float uniform() { return static_cast<float>(next() >> 8u) * 0x1p-24f; }

 private:
  std::uint64_t state_ = 0;
  std::uint64_t inc_;
};

}  // namespace pond::tree
