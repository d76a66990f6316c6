#pragma once
// The walk of a range of columns in chunks of a wide-float table's width, which every loop of the
// step kernel (step_kernel.h, tile_kernel.h) goes by.
#include "sim/isa_namespace.h"
#include "sim/wide_scalar.h"

// The kernel's helpers must be inlined into its loops: a call per 8 nodes costs more than the work.
#define POND_KERNEL_INLINE inline __attribute__((always_inline))

namespace pond::sim {
inline namespace POND_ISA {

// Calls fn.template operator()<V, Shifted>(j) for chunks of V::width columns [j, j + V::width)
// covering [begin, end): chunks of W while more than W::width columns remain, then one last chunk
// ending at `end`, which overlaps the one before it where the columns do not divide evenly (it
// recomputes some columns from the same inputs: the same bits). The last chunk is a chunk of
// W::Half (half as wide; half the cost where the wide unit is split in two, as on Zen 4) when that
// covers the rest. Shifted is true for a last chunk that starts before the columns not done yet.
// A range narrower than W is done with W::Half, or one column at a time with the scalar backend.
template <class W, class Fn>
POND_KERNEL_INLINE void for_chunks(int begin, int end, Fn&& fn) {
  using Half = typename W::Half;
  if (end - begin >= W::width) {
    int j = begin;
    for (; end - j > W::width; j += W::width) fn.template operator()<W, false>(j);
    if constexpr (Half::width < W::width) {
      if (end - j <= Half::width) {
        if (end - j < Half::width)
          fn.template operator()<Half, true>(end - Half::width);
        else
          fn.template operator()<Half, false>(j);
        return;
      }
    }
    if (end - j < W::width)
      fn.template operator()<W, true>(end - W::width);
    else
      fn.template operator()<W, false>(j);
  } else if constexpr (Half::width < W::width) {
    for_chunks<Half>(begin, end, fn);
  } else {
    for (int j = begin; j < end; ++j) fn.template operator()<WideScalar, false>(j);
  }
}

}  // namespace POND_ISA
}  // namespace pond::sim
