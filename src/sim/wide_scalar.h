#pragma once
// The scalar backend of the wide-float operation table (width 1). The solver kernel is written once
// against this table; every backend performs the very same IEEE operations in the very same order,
// so all of them produce the same bits. This one is also the reference and the tail loop of the
// others.
#include <bit>
#include <cstdint>

#include "sim/isa_namespace.h"

namespace pond::sim {
inline namespace POND_ISA {

struct WideScalar {
  using Half = WideScalar;  // no narrower tail chunk
  static constexpr int width = 1;
  using F = float;
  using M = std::uint32_t;  // all ones = true

  static F load(const float* p) { return *p; }
  static void store(float* p, F v) { *p = v; }
  static F set1(float v) { return v; }
  static F add(F a, F b) { return a + b; }
  static F sub(F a, F b) { return a - b; }
  static F mul(F a, F b) { return a * b; }
  static F neg(F a) { return -a; }  // flips the sign bit, also of zeros
  // The bit-trick seed of 1/sqrt(x): magic - (bits(x) >> 1), integer arithmetic on the bits.
  static F rsqrt_seed(F x, std::uint32_t magic) {
    return std::bit_cast<float>(magic - (std::bit_cast<std::uint32_t>(x) >> 1));
  }
  // True where the node kind byte is below `limit`.
  static M kind_below(const std::uint8_t* kinds, std::uint8_t limit) {
    return *kinds < limit ? ~0u : 0u;
  }
  // v where m, else +0 (a bitwise and: exact, and a constrained component becomes +0).
  static F keep(M m, F v) { return std::bit_cast<float>(std::bit_cast<std::uint32_t>(v) & m); }
  // max(acc, |v|): the running bound of the horizontal displacements (only an upper bound matters).
  static F max_abs(F acc, F v) {
    const F a = std::bit_cast<float>(std::bit_cast<std::uint32_t>(v) & 0x7fffffffu);
    return a > acc ? a : acc;
  }
  // v where it is below (above) acc, else acc: with acc never NaN, NaN values are skipped
  // (shared/tile_bounds.h; the SIMD tables' minps(v, acc) and maxps(v, acc)).
  static F min_of(F v, F acc) { return v < acc ? v : acc; }
  static F max_of(F v, F acc) { return v > acc ? v : acc; }
  // The least (greatest) lane of v, v free of NaN: its value is the same in any order.
  static float reduce_min(F v) { return v; }
  static float reduce_max(F v) { return v; }
  static float sum_lanes(F v) { return v; }
};

}  // namespace POND_ISA
}  // namespace pond::sim
