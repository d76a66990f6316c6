#pragma once
// The scalar backend of the wide-float operation table (width 1). The solver kernel is written once
// against this table; every backend performs the very same IEEE operations in the very same order,
// so all of them produce the same bits. This one is also the reference and the tail loop of the
// others. Below the solver's operations, those the LOD's scans and copies use (src/lod): every
// table has them, each lane doing what this one does.
#include <bit>
#include <cmath>
#include <cstddef>
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

  // The LOD's operations. Masks: all ones = true; compares are ordered (false where NaN).
  static F iota() { return 0.0f; }  // lane k holds k
  static F abs(F v) { return std::bit_cast<float>(std::bit_cast<std::uint32_t>(v) & 0x7fffffffu); }
  static F sqrt(F v) { return std::sqrt(v); }  // correctly rounded (IEEE), in every table
  static M less(F a, F b) { return a < b ? ~0u : 0u; }
  static M greater(F a, F b) { return a > b ? ~0u : 0u; }
  static M unordered(F a, F b) { return a != a || b != b ? ~0u : 0u; }
  static M none() { return 0u; }  // no lane true
  static M either(M a, M b) { return a | b; }
  static M both(M a, M b) { return a & b; }
  static F select(M m, F a, F b) { return m ? a : b; }  // a where m, else b
  static F bit_or(F a, F b) { return std::bit_cast<float>(std::bit_cast<std::uint32_t>(a) | std::bit_cast<std::uint32_t>(b)); }
  static bool any(M m) { return m != 0; }
  static unsigned lanes_set(M m) { return m & 1u; }  // bit k: lane k is true
  static M load_mask(const std::uint32_t* p) { return *p; }
  // Lane k of `even` and `odd`: p[2k] and p[2k + 1] (reads 2 * width floats).
  static void load_evens_odds(const float* p, F& even, F& odd) { even = p[0], odd = p[1]; }
  // Lane k of `first` and `second`: p[4k] and p[4k + 1] (pairs 4 floats apart); store_pairs writes
  // only those floats back.
  static void load_pairs(const float* p, F& first, F& second) { first = p[0], second = p[1]; }
  static void store_pairs(float* p, F first, F second) { p[0] = first, p[1] = second; }
  // Lane k of x, y, z: the first three floats of record k at r + k * stride (reads four of each;
  // stride >= 4).
  static void load_records(const float* r, std::size_t, F& x, F& y, F& z) { x = r[0], y = r[1], z = r[2]; }
};

}  // namespace POND_ISA
}  // namespace pond::sim
