// copy_finite_block()'s AVX2 copy (position_copy.h), chosen where the caller allows it and the CPU
// has AVX2: built with AVX2's flags and inline namespace (pond_isa_sources in src/lod/CMakeLists.txt).
#include <cstddef>

#include "lod/position_copy.h"
#include "sim/wide_avx2.h"

namespace pond::lod {

// A vector of columns at a time, the last vector of a row overlapping those before where the width
// does not divide (they are computed again from the same values: the same bits). Each node's
// operations are position_copy.cpp's, in its order (world: x = (col + ux) h, y = uy h,
// z = (row + uz) h), so the bits are the same; column numbers are exact in float (below 2^24).
// Returns whether some coordinate may not be finite: (x + y + z) * 0 is NaN then, +-0 otherwise.
bool copy_block_avx2(const NodePositions& p, int row0, int col0, int rows, int cols, float* x, float* y, float* z) {
  using W = sim::WideAvx2;
  using F = W::F;
  const std::size_t pitch = p.row_pitch, width = static_cast<std::size_t>(cols), last = width - W::width;
  const float *px = p.x, *py = p.y, *pz = p.z;
  const std::size_t stride = p.stride;
  const F h = W::set1(p.grid_spacing), zero = W::set1(0), lanes = W::iota();
  F seen = zero;
  // Row i's source nodes start at node `from`, its copies at i * width; `load` reads a vector of
  // nodes' coordinates, `convert` makes them world positions.
  const auto copy = [&](auto load, auto convert) {
    std::size_t from = static_cast<std::size_t>(row0) * pitch + static_cast<std::size_t>(col0);
    for (int i = 0; i < rows; ++i, from += pitch) {
      const F row = W::set1(static_cast<float>(row0 + i));
      float *tx = x + static_cast<std::size_t>(i) * width, *ty = y + (tx - x), *tz = z + (tx - x);
      for (std::size_t j = 0;; j = j + W::width < last ? j + W::width : last) {
        F v[3];
        load(v, from + j);
        convert(v, row, j);
        W::store(tx + j, v[0]), W::store(ty + j, v[1]), W::store(tz + j, v[2]);
        seen = W::bit_or(seen, W::mul(W::add(W::add(v[0], v[1]), v[2]), zero));
        if (j == last) break;
      }
    }
  };
  const auto arrays = [&](F* v, std::size_t n) { v[0] = W::load(px + n), v[1] = W::load(py + n), v[2] = W::load(pz + n); };
  // Interleaved records (x, y, z first, at least four floats each).
  const auto records = [&](F* v, std::size_t n) { W::load_records(px + n * stride, stride, v[0], v[1], v[2]); };
  const auto displaced = [&](F* v, F row, std::size_t j) {
    const F col = W::add(W::set1(static_cast<float>(col0 + static_cast<int>(j))), lanes);
    v[0] = W::mul(W::add(col, v[0]), h);
    v[1] = W::mul(v[1], h);
    v[2] = W::mul(W::add(row, v[2]), h);
  };
  const auto as_they_are = [](F*, F, std::size_t) {};
  if (stride != 1) copy(records, as_they_are);
  else if (p.grid_spacing > 0) copy(arrays, displaced);
  else copy(arrays, as_they_are);
  return W::any(W::unordered(seen, seen));
}

}  // namespace pond::lod
