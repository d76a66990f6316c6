#pragma once
// The NEON (AArch64 Advanced SIMD) backend of the wide-float operation table: 4 floats per
// operation, the baseline of every aarch64 CPU. Bit for bit the SSE2 table's twin: multiplies and
// adds stay separate instructions (vmulq, vaddq; never the fused vfma/vmla, and -ffp-contract=off
// keeps the compiler from fusing them), and min/max are compare-and-select with SSE2's operand
// rule (the second operand where unordered or equal), not FMIN/FMAX, whose -0 < +0 and NaN
// propagation differ from it.
#include <arm_neon.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "sim/isa_namespace.h"

namespace pond::sim {
inline namespace POND_ISA {

struct WideNeon {
  using Half = WideNeon;  // no narrower tail chunk
  static constexpr int width = 4;
  using F = float32x4_t;
  using M = uint32x4_t;

  static F load(const float* p) { return vld1q_f32(p); }
  static void store(float* p, F v) { vst1q_f32(p, v); }
  static F set1(float v) { return vdupq_n_f32(v); }
  static F add(F a, F b) { return vaddq_f32(a, b); }
  static F sub(F a, F b) { return vsubq_f32(a, b); }
  static F mul(F a, F b) { return vmulq_f32(a, b); }
  static F neg(F a) { return vreinterpretq_f32_u32(veorq_u32(vreinterpretq_u32_f32(a), vdupq_n_u32(0x80000000u))); }
  static F rsqrt_seed(F x, std::uint32_t magic) {
    return vreinterpretq_f32_u32(vsubq_u32(vdupq_n_u32(magic), vshrq_n_u32(vreinterpretq_u32_f32(x), 1)));
  }
  static M kind_below(const std::uint8_t* kinds, std::uint8_t limit) {
    std::uint32_t four;
    std::memcpy(&four, kinds, 4);
    const uint16x8_t k16 = vmovl_u8(vreinterpret_u8_u32(vdup_n_u32(four)));
    return vcltq_u32(vmovl_u16(vget_low_u16(k16)), vdupq_n_u32(limit));
  }
  static F keep(M m, F v) { return vreinterpretq_f32_u32(vandq_u32(m, vreinterpretq_u32_f32(v))); }
  static F max_abs(F acc, F v) { return max_of(abs(v), acc); }
  static F min_of(F v, F acc) { return vbslq_f32(vcltq_f32(v, acc), v, acc); }  // v < acc ? v : acc
  static F max_of(F v, F acc) { return vbslq_f32(vcgtq_f32(v, acc), v, acc); }  // v > acc ? v : acc
  // SSE2's order: lanes (0, 2) and (1, 3), then the first of those two against the second.
  static float reduce_min(F v) {
    const float32x2_t m = vget_low_f32(min_of(v, vcombine_f32(vget_high_f32(v), vget_high_f32(v))));
    const float a = vget_lane_f32(m, 0), b = vget_lane_f32(m, 1);
    return a < b ? a : b;
  }
  static float reduce_max(F v) {
    const float32x2_t m = vget_low_f32(max_of(v, vcombine_f32(vget_high_f32(v), vget_high_f32(v))));
    const float a = vget_lane_f32(m, 0), b = vget_lane_f32(m, 1);
    return a > b ? a : b;
  }
  static float sum_lanes(F v) {
    return (vgetq_lane_f32(v, 0) + vgetq_lane_f32(v, 1)) + (vgetq_lane_f32(v, 2) + vgetq_lane_f32(v, 3));
  }

  // The LOD's operations (wide_scalar.h).
  static F iota() {
    static constexpr float k[4] = {0, 1, 2, 3};
    return vld1q_f32(k);
  }
  static F abs(F v) { return vreinterpretq_f32_u32(vandq_u32(vreinterpretq_u32_f32(v), vdupq_n_u32(0x7fffffffu))); }
  static F sqrt(F v) { return vsqrtq_f32(v); }
  static M less(F a, F b) { return vcltq_f32(a, b); }
  static M greater(F a, F b) { return vcgtq_f32(a, b); }
  static M unordered(F a, F b) { return vmvnq_u32(vandq_u32(vceqq_f32(a, a), vceqq_f32(b, b))); }
  static M none() { return vdupq_n_u32(0); }
  static M either(M a, M b) { return vorrq_u32(a, b); }
  static M both(M a, M b) { return vandq_u32(a, b); }
  static F select(M m, F a, F b) { return vbslq_f32(m, a, b); }
  static F bit_or(F a, F b) { return vreinterpretq_f32_u32(vorrq_u32(vreinterpretq_u32_f32(a), vreinterpretq_u32_f32(b))); }
  static bool any(M m) { return vmaxvq_u32(m) != 0; }
  static unsigned lanes_set(M m) {
    static constexpr std::uint32_t bit[4] = {1, 2, 4, 8};
    return vaddvq_u32(vandq_u32(m, vld1q_u32(bit)));
  }
  static M load_mask(const std::uint32_t* p) { return vld1q_u32(p); }
  static void load_evens_odds(const float* p, F& even, F& odd) {
    const float32x4x2_t v = vld2q_f32(p);
    even = v.val[0], odd = v.val[1];
  }
  static void load_pairs(const float* p, F& first, F& second) {
    const F p01 = vcombine_f32(vld1_f32(p), vld1_f32(p + 4)), p23 = vcombine_f32(vld1_f32(p + 8), vld1_f32(p + 12));
    first = vuzp1q_f32(p01, p23), second = vuzp2q_f32(p01, p23);
  }
  static void store_pairs(float* p, F first, F second) {
    const F lo = vzip1q_f32(first, second), hi = vzip2q_f32(first, second);
    vst1_f32(p, vget_low_f32(lo)), vst1_f32(p + 4, vget_high_f32(lo));
    vst1_f32(p + 8, vget_low_f32(hi)), vst1_f32(p + 12, vget_high_f32(hi));
  }
  static void load_records(const float* r, std::size_t stride, F& x, F& y, F& z) {
    // (x y z w) of records 0 .. 3 -> trn: (x0 x1 z0 z1), (y0 y1 w0 w1) and the same of 2, 3.
    const float32x4x2_t t01 = vtrnq_f32(vld1q_f32(r), vld1q_f32(r + stride));
    const float32x4x2_t t23 = vtrnq_f32(vld1q_f32(r + 2 * stride), vld1q_f32(r + 3 * stride));
    x = vcombine_f32(vget_low_f32(t01.val[0]), vget_low_f32(t23.val[0]));
    y = vcombine_f32(vget_low_f32(t01.val[1]), vget_low_f32(t23.val[1]));
    z = vcombine_f32(vget_high_f32(t01.val[0]), vget_high_f32(t23.val[0]));
  }
};

}  // namespace POND_ISA
}  // namespace pond::sim
