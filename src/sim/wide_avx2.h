#pragma once
// The AVX2 backend of the wide-float operation table: 8 floats per operation. Compiled only in the
// translation unit built with -mavx2 (never -mfma: a fused multiply-add rounds once instead of
// twice and would change the bits).
#include <cstddef>
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

  // The LOD's operations (wide_scalar.h). The compares are SSE2's (ordered, signalling).
  static F iota() { return _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7); }
  static F abs(F v) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), v); }
  static F sqrt(F v) { return _mm256_sqrt_ps(v); }
  static M less(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_LT_OS); }
  static M greater(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_GT_OS); }
  static M unordered(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_UNORD_Q); }
  static M none() { return _mm256_setzero_ps(); }
  static M either(M a, M b) { return _mm256_or_ps(a, b); }
  static M both(M a, M b) { return _mm256_and_ps(a, b); }
  static F select(M m, F a, F b) { return _mm256_blendv_ps(b, a, m); }
  static F bit_or(F a, F b) { return _mm256_or_ps(a, b); }
  static bool any(M m) { return _mm256_movemask_ps(m) != 0; }
  static unsigned lanes_set(M m) { return static_cast<unsigned>(_mm256_movemask_ps(m)); }
  static M load_mask(const std::uint32_t* p) {
    return _mm256_castsi256_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)));
  }
  // Lanes 0-3 from lo, 4-7 from hi: two four-float loads (the LOD's scan of short row pieces).
  static F load_halves(const float* lo, const float* hi) { return _mm256_loadu2_m128(hi, lo); }
  // Records k and k + 4 in the two halves, each four-by-four transposed in its half.
  static void load_records(const float* r, std::size_t stride, F& x, F& y, F& z) {
    const auto pair = [&](std::size_t k) { return _mm256_loadu2_m128(r + (k + 4) * stride, r + k * stride); };
    const __m256 a0 = pair(0), a1 = pair(1), a2 = pair(2), a3 = pair(3);
    const __m256 xy01 = _mm256_unpacklo_ps(a0, a1), xy23 = _mm256_unpacklo_ps(a2, a3);
    const __m256 zw01 = _mm256_unpackhi_ps(a0, a1), zw23 = _mm256_unpackhi_ps(a2, a3);
    x = _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(1, 0, 1, 0));
    y = _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(3, 2, 3, 2));
    z = _mm256_shuffle_ps(zw01, zw23, _MM_SHUFFLE(1, 0, 1, 0));
  }
};

}  // namespace POND_ISA
}  // namespace pond::sim
