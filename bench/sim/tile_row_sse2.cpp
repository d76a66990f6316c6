// Built with the baseline flags, as kernel_sse2.cpp is (x86-64 has SSE2).
#include "tile_row_alone_impl.h"
#include "sim/wide_sse2.h"

namespace pond::bench {
TileRowFn tile_row_sse2() { return &tile_row_alone<sim::WideSse2>; }
}  // namespace pond::bench
