#pragma once
// The SSE2 backend of the wide-float operation table: 4 floats per operation. SSE2 is the
// Pentium 4 / IA-32 baseline the paper's "next step" names; the same header builds for -m32.
#include <cstdint>
#include <cstring>
#include <emmintrin.h>

#include "sim/isa_namespace.h"

namespace pond::sim {
inline namespace POND_ISA {

struct WideSse2 {
  using Half = WideSse2;  // no narrower tail chunk
  static constexpr int width = 4;
  using F = __m128;
  using M = __m128;

  static F load(const float* p) { return _mm_loadu_ps(p); }
  static void store(float* p, F v) { _mm_storeu_ps(p, v); }
  static F set1(float v) { return _mm_set1_ps(v); }
  static F add(F a, F b) { return _mm_add_ps(a, b); }
  static F sub(F a, F b) { return _mm_sub_ps(a, b); }
  static F mul(F a, F b) { return _mm_mul_ps(a, b); }
  static F neg(F a) { return _mm_xor_ps(a, _mm_set1_ps(-0.0f)); }
  static F rsqrt_seed(F x, std::uint32_t magic) {
    const __m128i bits = _mm_srli_epi32(_mm_castps_si128(x), 1);
    return _mm_castsi128_ps(_mm_sub_epi32(_mm_set1_epi32(static_cast<int>(magic)), bits));
  }
  static M kind_below(const std::uint8_t* kinds, std::uint8_t limit) {
    std::int32_t four;
    std::memcpy(&four, kinds, 4);
    const __m128i zero = _mm_setzero_si128();
    const __m128i k = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(four), zero), zero);
    return _mm_castsi128_ps(_mm_cmplt_epi32(k, _mm_set1_epi32(limit)));
  }
  static F keep(M m, F v) { return _mm_and_ps(m, v); }
  static F max_abs(F acc, F v) { return _mm_max_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), v), acc); }
  static F min_of(F v, F acc) { return _mm_min_ps(v, acc); }  // v < acc ? v : acc, per lane
  static F max_of(F v, F acc) { return _mm_max_ps(v, acc); }  // v > acc ? v : acc
  static float reduce_min(F v) {
    v = _mm_min_ps(v, _mm_movehl_ps(v, v));
    return _mm_cvtss_f32(_mm_min_ss(v, _mm_shuffle_ps(v, v, 1)));
  }
  static float reduce_max(F v) {
    v = _mm_max_ps(v, _mm_movehl_ps(v, v));
    return _mm_cvtss_f32(_mm_max_ss(v, _mm_shuffle_ps(v, v, 1)));
  }
  static float sum_lanes(F v) {
    alignas(16) float l[4];
    _mm_store_ps(l, v);
    return (l[0] + l[1]) + (l[2] + l[3]);
  }
};

}  // namespace POND_ISA
}  // namespace pond::sim
