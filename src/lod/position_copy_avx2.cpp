// copy_finite_block()'s AVX2 copy (position_copy.h), chosen where the caller allows it and the CPU
// has AVX2.
#include <immintrin.h>

#include <cstddef>

#include "lod/position_copy.h"

namespace pond::lod {

// Eight columns at a time, the last eight of a row overlapping those before where the width does
// not divide (they are computed again from the same values: the same bits). Each node's operations
// are position_copy.cpp's, in its order (world: x = (col + ux) h, y = uy h, z = (row + uz) h), so
// the bits are the same; column numbers are exact in float (below 2^24). Returns whether some
// coordinate may not be finite: (x + y + z) * 0 is NaN then, +-0 otherwise.
bool copy_block_avx2(const NodePositions& p, int row0, int col0, int rows, int cols, float* x, float* y, float* z) {
  const std::size_t pitch = p.row_pitch, width = static_cast<std::size_t>(cols), last = width - 8;
  const float *px = p.x, *py = p.y, *pz = p.z;
  const std::size_t stride = p.stride;
  const __m256 h = _mm256_set1_ps(p.grid_spacing), zero = _mm256_setzero_ps();
  const __m256 lanes = _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7);
  __m256 seen = zero;
  // Row i's source nodes start at node `from`, its copies at i * width; `load` reads eight nodes'
  // coordinates, `convert` makes them world positions.
  const auto copy = [&](auto load, auto convert) {
    std::size_t from = static_cast<std::size_t>(row0) * pitch + static_cast<std::size_t>(col0);
    for (int i = 0; i < rows; ++i, from += pitch) {
      const __m256 row = _mm256_set1_ps(static_cast<float>(row0 + i));
      float *tx = x + static_cast<std::size_t>(i) * width, *ty = y + (tx - x), *tz = z + (tx - x);
      for (std::size_t j = 0;; j = j + 8 < last ? j + 8 : last) {
        __m256 v[3];
        load(v, from + j);
        convert(v, row, j);
        _mm256_storeu_ps(tx + j, v[0]), _mm256_storeu_ps(ty + j, v[1]), _mm256_storeu_ps(tz + j, v[2]);
        seen = _mm256_or_ps(seen, _mm256_mul_ps(_mm256_add_ps(_mm256_add_ps(v[0], v[1]), v[2]), zero));
        if (j == last) break;
      }
    }
  };
  const auto arrays = [&](__m256* v, std::size_t n) {
    v[0] = _mm256_loadu_ps(px + n), v[1] = _mm256_loadu_ps(py + n), v[2] = _mm256_loadu_ps(pz + n);
  };
  // Interleaved records (x, y, z first, at least four floats each): records n..n+3 and n+4..n+7 in
  // the two halves, each four-by-four transposed in its half.
  const auto records = [&](__m256* v, std::size_t n) {
    const float* r = px + n * stride;
    const auto pair = [&](std::size_t k) { return _mm256_loadu2_m128(r + (k + 4) * stride, r + k * stride); };
    const __m256 a0 = pair(0), a1 = pair(1), a2 = pair(2), a3 = pair(3);
    const __m256 xy01 = _mm256_unpacklo_ps(a0, a1), xy23 = _mm256_unpacklo_ps(a2, a3);
    const __m256 zw01 = _mm256_unpackhi_ps(a0, a1), zw23 = _mm256_unpackhi_ps(a2, a3);
    v[0] = _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(1, 0, 1, 0));
    v[1] = _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(3, 2, 3, 2));
    v[2] = _mm256_shuffle_ps(zw01, zw23, _MM_SHUFFLE(1, 0, 1, 0));
  };
  const auto displaced = [&](__m256* v, __m256 row, std::size_t j) {
    const __m256 col = _mm256_add_ps(_mm256_set1_ps(static_cast<float>(col0 + static_cast<int>(j))), lanes);
    v[0] = _mm256_mul_ps(_mm256_add_ps(col, v[0]), h);
    v[1] = _mm256_mul_ps(v[1], h);
    v[2] = _mm256_mul_ps(_mm256_add_ps(row, v[2]), h);
  };
  const auto as_they_are = [](__m256*, __m256, std::size_t) {};
  if (stride != 1) copy(records, as_they_are);
  else if (p.grid_spacing > 0) copy(arrays, displaced);
  else copy(arrays, as_they_are);
  return _mm256_movemask_ps(_mm256_cmp_ps(seen, seen, _CMP_UNORD_Q)) != 0;
}

}  // namespace pond::lod
