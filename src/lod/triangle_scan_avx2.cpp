// The exact scan's AVX2 copy (scan_rows.h), chosen by within_budget where ScanBudgets::wide, and
// that of the thresholds it compares with (scan_thresholds()).
#include <immintrin.h>

#include "lod/scan_rows.h"

namespace pond::lod {
namespace {

// scan_rows.h's lanes with AVX2: eight floats. The compares are the SSE2 copy's (ordered, on
// values that are never NaN).
struct Avx2Lanes {
  using V = __m256;
  static constexpr int width = 8;
  static V set1(float v) { return _mm256_set1_ps(v); }
  template <int i>
  static V splat(__m128 v) { return _mm256_broadcastss_ps(_mm_shuffle_ps(v, v, _MM_SHUFFLE(i, i, i, i))); }
  static V iota() { return _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7); }
  static V load(const float* p) { return _mm256_loadu_ps(p); }
  static V add(V a, V b) { return _mm256_add_ps(a, b); }
  static V sub(V a, V b) { return _mm256_sub_ps(a, b); }
  static V mul(V a, V b) { return _mm256_mul_ps(a, b); }
  static V and_(V a, V b) { return _mm256_and_ps(a, b); }
  static V or_(V a, V b) { return _mm256_or_ps(a, b); }
  static V less(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_LT_OS); }
  static V greater(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_GT_OS); }
  static bool any(V m) { return _mm256_movemask_ps(m) != 0; }
  static constexpr bool pairs = true;  // two row pieces a group (scan_rows.h's group_scan)
  static V load_pair(const float* lo, const float* hi) { return _mm256_loadu2_m128(hi, lo); }
  static V load_mask(const std::uint32_t* m) {
    return _mm256_castsi256_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(m)));
  }
  static bool lane(V m, int k) { return (_mm256_movemask_ps(m) >> k & 1) != 0; }
};

}  // namespace

void scan_thresholds_avx2(const float* budget, std::size_t n, float largest, float* sure2) {
  const __m256 slack = _mm256_set1_ps(scan_slack(largest)), shrink = _mm256_set1_ps(1 - 1e-6f);
  const __m256 zero = _mm256_setzero_ps();
  for (std::size_t k = 0; k < n; k += 8) {  // the last group's lanes past n into the padding
    const __m256 low = _mm256_max_ps(_mm256_sub_ps(_mm256_loadu_ps(budget + k), slack), zero);
    _mm256_storeu_ps(sure2 + k, _mm256_mul_ps(_mm256_mul_ps(low, low), shrink));
  }
}

bool scan_triangle_avx2(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets, float largest,
                        const Tri& t, const TriCorners* c, const Tri& region, long long* visited) {
  return scan_triangle<Avx2Lanes>(grid, p, budgets, largest, t, c, region, visited);
}

}  // namespace pond::lod
