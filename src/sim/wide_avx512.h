#pragma once
// The AVX-512 backend of the wide-float operation table: 16 floats per operation. Compiled only in
// the translation unit built with -mavx512f; no FMA intrinsic is used and -ffp-contract=off keeps
// the compiler from fusing, so the bits equal every other backend's.
#include <cstdint>
#include <immintrin.h>

#include "sim/isa_namespace.h"
#include "sim/wide_avx2.h"

namespace pond::sim {
inline namespace POND_ISA {

struct WideAvx512 {
  using Half = WideAvx2;  // the tail chunk when it covers the rest (see for_chunks)
  static constexpr int width = 16;
  using F = __m512;
  using M = __mmask16;

  static F load(const float* p) { return _mm512_loadu_ps(p); }
  static void store(float* p, F v) { _mm512_storeu_ps(p, v); }
  static F set1(float v) { return _mm512_set1_ps(v); }
  static F add(F a, F b) { return _mm512_add_ps(a, b); }
  static F sub(F a, F b) { return _mm512_sub_ps(a, b); }
  static F mul(F a, F b) { return _mm512_mul_ps(a, b); }
  static F neg(F a) {
    return _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(a), _mm512_set1_epi32(INT32_MIN)));
  }
  static F rsqrt_seed(F x, std::uint32_t magic) {
    // The masked form: GCC 12 warns (falsely) about the undefined pass-through of the plain one.
    const __m512i bits = _mm512_maskz_srli_epi32(0xffff, _mm512_castps_si512(x), 1);
    return _mm512_castsi512_ps(_mm512_sub_epi32(_mm512_set1_epi32(static_cast<int>(magic)), bits));
  }
  static M kind_below(const std::uint8_t* kinds, std::uint8_t limit) {
    const __m512i k =
        _mm512_maskz_cvtepu8_epi32(0xffff, _mm_loadu_si128(reinterpret_cast<const __m128i*>(kinds)));
    return _mm512_cmplt_epi32_mask(k, _mm512_set1_epi32(limit));
  }
  static F keep(M m, F v) { return _mm512_maskz_mov_ps(m, v); }  // +0 where not m
  static F max_abs(F acc, F v) {
    const __m512 a = _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(v), _mm512_set1_epi32(INT32_MAX)));
    return _mm512_maskz_max_ps(0xffff, a, acc);  // the masked form: see rsqrt_seed
  }
  // v < acc ? v : acc per lane (v > acc ? v : acc); the masked forms: see rsqrt_seed.
  static F min_of(F v, F acc) { return _mm512_maskz_min_ps(0xffff, v, acc); }
  static F max_of(F v, F acc) { return _mm512_maskz_max_ps(0xffff, v, acc); }
  // The half `h` (0 low, 1 high) by the masked extract (see rsqrt_seed); reductions halve, then AVX2's.
  template <int h>
  static __m256 half(F v) {
    return _mm256_castpd_ps(_mm512_maskz_extractf64x4_pd(0xf, _mm512_castps_pd(v), h));
  }
  static float reduce_min(F v) { return WideAvx2::reduce_min(_mm256_min_ps(half<0>(v), half<1>(v))); }
  static float reduce_max(F v) { return WideAvx2::reduce_max(_mm256_max_ps(half<0>(v), half<1>(v))); }
  static float sum_lanes(F v) {
    alignas(64) float l[16];
    _mm512_store_ps(l, v);
    float s = 0.0f;
    for (float x : l) s += x;
    return s;
  }
};

}  // namespace POND_ISA
}  // namespace pond::sim
