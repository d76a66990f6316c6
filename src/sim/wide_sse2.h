#pragma once
// The SSE2 backend of the wide-float operation table: 4 floats per operation. SSE2 is the
// Pentium 4 / IA-32 baseline the paper's "next step" names; the same header builds for -m32.
#include <cstddef>
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

  // The LOD's operations (wide_scalar.h).
  static F iota() { return _mm_setr_ps(0, 1, 2, 3); }
  static F abs(F v) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), v); }
  static F sqrt(F v) { return _mm_sqrt_ps(v); }
  static M less(F a, F b) { return _mm_cmplt_ps(a, b); }
  static M greater(F a, F b) { return _mm_cmpgt_ps(a, b); }
  static M unordered(F a, F b) { return _mm_cmpunord_ps(a, b); }
  static M none() { return _mm_setzero_ps(); }
  static M either(M a, M b) { return _mm_or_ps(a, b); }
  static M both(M a, M b) { return _mm_and_ps(a, b); }
  static F select(M m, F a, F b) { return _mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b)); }
  static F bit_or(F a, F b) { return _mm_or_ps(a, b); }
  static bool any(M m) { return _mm_movemask_ps(m) != 0; }
  static unsigned lanes_set(M m) { return static_cast<unsigned>(_mm_movemask_ps(m)); }
  static M load_mask(const std::uint32_t* p) { return _mm_castsi128_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p))); }
  static void load_evens_odds(const float* p, F& even, F& odd) {
    const __m128 a = _mm_loadu_ps(p), b = _mm_loadu_ps(p + 4);
    even = _mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0));
    odd = _mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1));
  }
  static void load_pairs(const float* p, F& first, F& second) {
    const auto pair = [&](int k) { return _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(p + 4 * k)); };
    const __m128 t0 = _mm_unpacklo_ps(pair(0), pair(1)), t1 = _mm_unpacklo_ps(pair(2), pair(3));
    first = _mm_movelh_ps(t0, t1);
    second = _mm_movehl_ps(t1, t0);
  }
  static void store_pairs(float* p, F first, F second) {
    const __m128 lo = _mm_unpacklo_ps(first, second), hi = _mm_unpackhi_ps(first, second);
    _mm_storel_pi(reinterpret_cast<__m64*>(p), lo), _mm_storeh_pi(reinterpret_cast<__m64*>(p + 4), lo);
    _mm_storel_pi(reinterpret_cast<__m64*>(p + 8), hi), _mm_storeh_pi(reinterpret_cast<__m64*>(p + 12), hi);
  }
  static void load_records(const float* r, std::size_t stride, F& x, F& y, F& z) {
    __m128 a = _mm_loadu_ps(r), b = _mm_loadu_ps(r + stride), c = _mm_loadu_ps(r + 2 * stride);
    __m128 unused = _mm_loadu_ps(r + 3 * stride);
    _MM_TRANSPOSE4_PS(a, b, c, unused);
    x = a, y = b, z = c;
  }
};

}  // namespace POND_ISA
}  // namespace pond::sim
