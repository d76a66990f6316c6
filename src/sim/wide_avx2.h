#pragma once
// The AVX2 backend of the wide-float operation table: 8 floats per operation. Compiled only in the
// translation unit built with -mavx2 (never -mfma: a fused multiply-add rounds once instead of
// twice and would change the bits).
#include <cstdint>
#include <immintrin.h>

#include "sim/isa_namespace.h"

namespace pond::sim {
inline namespace POND_ISA {

struct WideAvx2 {
  using Half = WideAvx2;  // no narrower tail chunk (a 4-wide one costs as much on Zen 4)
  static constexpr int width = 8;
  using F = __m256;
  using M = __m256;

  static F load(const float* p) { return _mm256_loadu_ps(p); }
  static void store(float* p, F v) { _mm256_storeu_ps(p, v); }
  static F set1(float v) { return _mm256_set1_ps(v); }
  static F add(F a, F b) { return _mm256_add_ps(a, b); }
  static F sub(F a, F b) { return _mm256_sub_ps(a, b); }
  static F mul(F a, F b) { return _mm256_mul_ps(a, b); }
  static F neg(F a) { return _mm256_xor_ps(a, _mm256_set1_ps(-0.0f)); }
  static F rsqrt_seed(F x, std::uint32_t magic) {
    const __m256i bits = _mm256_srli_epi32(_mm256_castps_si256(x), 1);
    return _mm256_castsi256_ps(_mm256_sub_epi32(_mm256_set1_epi32(static_cast<int>(magic)), bits));
  }
  static M kind_below(const std::uint8_t* kinds, std::uint8_t limit) {
    const __m256i k = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(kinds)));
    return _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_set1_epi32(limit), k));
  }
  static F keep(M m, F v) { return _mm256_and_ps(m, v); }
  static F max_abs(F acc, F v) { return _mm256_max_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), v), acc); }
  static F min_of(F v, F acc) { return _mm256_min_ps(v, acc); }  // v < acc ? v : acc, per lane
  static F max_of(F v, F acc) { return _mm256_max_ps(v, acc); }  // v > acc ? v : acc
  static float reduce_min(F v) {
    __m128 m = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_min_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_min_ss(m, _mm_shuffle_ps(m, m, 1)));
  }
  static float reduce_max(F v) {
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
  }
  static float sum_lanes(F v) {
    alignas(32) float l[8];
    _mm256_store_ps(l, v);
    return ((l[0] + l[1]) + (l[2] + l[3])) + ((l[4] + l[5]) + (l[6] + l[7]));
  }
};

}  // namespace POND_ISA
}  // namespace pond::sim
