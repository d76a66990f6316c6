// Built with the sse2 kernel's flags (bench/sim/CMakeLists.txt).
#include "tile_row_alone_impl.h"
#include "sim/wide_sse2.h"

namespace pond::bench {
TileRowFn tile_row_sse2() { return &tile_row_alone<sim::WideSse2>; }
}  // namespace pond::bench
