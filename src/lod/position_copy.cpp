#include "lod/position_copy.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "core/errors.h"
#include "lod/camera_budget.h"
#include "sim/wide_baseline.h"

namespace pond::lod {
namespace {

// The copies' table where the AVX2 copy does not run: SSE2 or NEON, four nodes at a time.
using W = sim::WideBaseline;
using F = W::F;

// The largest magnitude is returned as a bit pattern with the sign cleared: those order like the
// magnitudes, with inf and NaN above every finite value.
std::uint32_t magnitude_bits(float v) { return std::bit_cast<std::uint32_t>(v) & 0x7fffffffu; }

// What a copy learns of the coordinates on the way, a vector of nodes at a time and then the tail.
// LargestMagnitude: the largest |coordinate|, in floats: `big` keeps the largest magnitudes (inf
// included) and `nan` flags a NaN, which a vector maximum alone would drop (fewer operations than a
// maximum on bit patterns, which SSE2 has no instruction for). Its bits() are those of magnitude_bits.
struct LargestMagnitude {
  F big = W::set1(0);
  W::M nan = W::none();
  std::uint32_t tail = 0;
  void add(F x, F y, F z) {
    big = W::max_of(big, W::max_of(W::max_of(W::abs(x), W::abs(y)), W::abs(z)));
    nan = W::either(nan, W::either(W::unordered(x, y), W::unordered(z, z)));
  }
  void add(float x, float y, float z) { tail = std::max({tail, magnitude_bits(x), magnitude_bits(y), magnitude_bits(z)}); }
  std::uint32_t bits() const {
    if (W::any(nan)) return 0x7fc00000u;  // a quiet NaN
    return std::max(tail, magnitude_bits(W::reduce_max(big)));  // no NaN: the same in any order
  }
};

// MaybeNotFinite: only whether a coordinate might not be finite, for copies that need no largest.
// (x + y + z) * 0 is NaN when one is inf or NaN (or, harmlessly, when the sum overflows), else
// +-0; OR-ing the bit patterns keeps a NaN's (all exponent bits, some mantissa bit) and, unlike a
// sum, makes no long chain of latencies.
struct MaybeNotFinite {
  F seen = W::set1(0);
  float tail = 0;
  void add(F x, F y, F z) { seen = W::bit_or(seen, W::mul(W::add(W::add(x, y), z), W::set1(0))); }
  void add(float x, float y, float z) { tail += (x + y + z) * 0.0f; }
  bool any() const { return W::any(W::unordered(seen, seen)) || tail != tail; }
};

// Displacements in grid units -> world: x = (col + ux) * h, y = uy * h, z = (row + uz) * h, row by
// row (no division per node), a vector of columns at a time. Vector adds and multiplies round like
// the scalar ones, so every node gets the same bits as the scalar tail.
template <class Tracker>
void copy_displacements(const NodePositions& p, int row0, int col0, int rows, int window_cols, float* x, float* y,
                        float* z, Tracker& seen) {
  const std::size_t cols = static_cast<std::size_t>(window_cols), stride = p.stride, pitch = p.row_pitch;
  const std::size_t first = static_cast<std::size_t>(row0) * pitch + static_cast<std::size_t>(col0);
  const float h = p.grid_spacing;
  const F hw = W::set1(h), step = W::set1(W::width);
  // Row i's source nodes start at i * pitch, its copies at i * cols.
  const float fc = static_cast<float>(col0);
  for (std::size_t i = 0, row = 0, src_row = first; i < static_cast<std::size_t>(rows);
       ++i, row += cols, src_row += pitch) {
    const float fi = static_cast<float>(static_cast<std::size_t>(row0) + i);
    std::size_t j = 0;
    if (stride == 1) {
      const F fiw = W::set1(fi);
      F fjw = W::add(W::set1(fc), W::iota());  // column numbers: exact in float (below 2^24)
      for (; j + W::width <= cols; j += W::width, fjw = W::add(fjw, step)) {
        const std::size_t k = row + j, s = src_row + j;
        const F vx = W::mul(W::add(fjw, W::load(p.x + s)), hw);
        const F vy = W::mul(W::load(p.y + s), hw);
        const F vz = W::mul(W::add(fiw, W::load(p.z + s)), hw);
        W::store(x + k, vx), W::store(y + k, vy), W::store(z + k, vz);
        seen.add(vx, vy, vz);
      }
    }
    for (; j < cols; ++j) {
      const std::size_t k = row + j, s = (src_row + j) * stride;
      x[k] = (static_cast<float>(static_cast<std::size_t>(col0) + j) + p.x[s]) * h;
      y[k] = p.y[s] * h;
      z[k] = (fi + p.z[s]) * h;
      seen.add(x[k], y[k], z[k]);
    }
  }
}

// Copies n records of `stride` floats (x at px[k * stride], ...) to x[k], y[k], z[k].
template <class Tracker>
void copy_records(const float* px, const float* py, const float* pz, std::size_t stride, std::size_t n, float* x,
                  float* y, float* z, Tracker& seen) {
  std::size_t k = 0;
  if (py == px + 1 && pz == px + 2 && stride >= 4) {
    // Interleaved records (STATE.npy: x, y, z, vx, vy, vz): each record's first four floats are
    // one load, a vector's records are transposed into x, y, z vectors.
    for (; k + W::width <= n; k += W::width) {
      F vx, vy, vz;
      W::load_records(px + k * stride, stride, vx, vy, vz);
      W::store(x + k, vx), W::store(y + k, vy), W::store(z + k, vz);
      seen.add(vx, vy, vz);
    }
  }
  for (; k < n; ++k) {
    x[k] = px[k * stride], y[k] = py[k * stride], z[k] = pz[k * stride];
    seen.add(x[k], y[k], z[k]);
  }
}

template <class Tracker>
void copy_window_with(const NodePositions& p, int row0, int col0, int rows, int window_cols, float* x, float* y,
                      float* z, Tracker& seen) {
  if (p.grid_spacing > 0) return copy_displacements(p, row0, col0, rows, window_cols, x, y, z, seen);
  const std::size_t cols = static_cast<std::size_t>(window_cols), stride = p.stride;
  const std::size_t first = static_cast<std::size_t>(row0) * p.row_pitch + static_cast<std::size_t>(col0);
  // A compact whole view is one run of rows * cols records; otherwise, one run per row.
  if (p.row_pitch == cols && first == 0 && rows == p.rows && window_cols == p.cols)
    return copy_records(p.x, p.y, p.z, stride, p.nodes(), x, y, z, seen);
  for (std::size_t i = 0; i < static_cast<std::size_t>(rows); ++i) {
    const std::size_t from = (first + i * p.row_pitch) * stride, to = i * cols;
    copy_records(p.x + from, p.y + from, p.z + from, stride, cols, x + to, y + to, z + to, seen);
  }
}

// Throws InputError naming the first node of the copied window with a non-finite coordinate.
void name_non_finite(const NodePositions& p, int row0, int col0, int rows, int cols, const float* x, const float* y,
                     const float* z) {
  for (int k = 0; k < rows * cols; ++k)
    if (!std::isfinite(x[k]) || !std::isfinite(y[k]) || !std::isfinite(z[k])) {
      const std::size_t row = static_cast<std::size_t>(row0 + k / cols), col = static_cast<std::size_t>(col0 + k % cols);
      throw InputError("node " + std::to_string(row * static_cast<std::size_t>(p.cols) + col) + " (row " +
                       std::to_string(row) + ", col " + std::to_string(col) + ") has a non-finite position");
    }
}

}  // namespace

float copy_positions(const NodePositions& p, float* x, float* y, float* z) {
  return copy_window(p, 0, 0, p.rows, p.cols, x, y, z);
}

float copy_window(const NodePositions& p, int row0, int col0, int rows, int window_cols, float* x, float* y,
                  float* z) {
  LargestMagnitude seen;
  copy_window_with(p, row0, col0, rows, window_cols, x, y, z, seen);
  return std::bit_cast<float>(seen.bits());
}

float copy_finite_window(const NodePositions& p, int row0, int col0, int rows, int cols, float* x, float* y,
                         float* z) {
  const float largest = copy_window(p, row0, col0, rows, cols, x, y, z);
  if (!(largest <= std::numeric_limits<float>::max())) name_non_finite(p, row0, col0, rows, cols, x, y, z);  // inf, NaN
  return largest;
}

void copy_finite_block(const NodePositions& p, int row0, int col0, int rows, int cols, float* x, float* y, float* z,
                       [[maybe_unused]] bool wide) {
  bool maybe_not_finite;
#if POND_LOD_AVX2
  // The AVX2 copy's layouts: arrays, and records of world positions starting x, y, z.
  const bool records = p.stride >= 4 && p.y == p.x + 1 && p.z == p.x + 2 && p.grid_spacing <= 0;
  if (wide && (p.stride == 1 || records) && cols >= 8 && wide_budgets_available()) {
    maybe_not_finite = copy_block_avx2(p, row0, col0, rows, cols, x, y, z);
  } else
#endif
  {
    MaybeNotFinite seen;
    copy_window_with(p, row0, col0, rows, cols, x, y, z, seen);
    maybe_not_finite = seen.any();
  }
  if (maybe_not_finite) name_non_finite(p, row0, col0, rows, cols, x, y, z);
}

std::array<float, 3> world_position(const NodePositions& p, int row, int col) {
  const std::size_t s = (static_cast<std::size_t>(row) * p.row_pitch + static_cast<std::size_t>(col)) * p.stride;
  if (p.grid_spacing <= 0) return {p.x[s], p.y[s], p.z[s]};
  // As copy_displacements, operation for operation.
  return {(static_cast<float>(col) + p.x[s]) * p.grid_spacing, p.y[s] * p.grid_spacing,
          (static_cast<float>(row) + p.z[s]) * p.grid_spacing};
}

void copy_nodes(const NodePositions& p, std::span<const std::uint32_t> ids, float* x, float* y, float* z) {
  // Each id's row by a multiply, not a division: (id + 0.5) / cols lies at least 0.5 / cols >= 2^-17
  // from an integer (cols <= 2^16), and in double it errs by at most 2^-36 (the quotient is below
  // rows <= 2^16), so its integer part is the row.
  const std::uint32_t cols = static_cast<std::uint32_t>(p.cols);
  const double inverse = 1.0 / static_cast<double>(cols);
  for (std::uint32_t id : ids) {
    const std::uint32_t row = static_cast<std::uint32_t>((static_cast<double>(id) + 0.5) * inverse);
    const auto w = world_position(p, static_cast<int>(row), static_cast<int>(id - row * cols));
    x[id] = w[0], y[id] = w[1], z[id] = w[2];
  }
}

}  // namespace pond::lod
