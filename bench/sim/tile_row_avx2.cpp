// Built with the avx2 kernel's flags (bench/sim/CMakeLists.txt).
#include "tile_row_alone_impl.h"
#include "sim/wide_avx2.h"

namespace pond::bench {
TileRowFn tile_row_avx2() { return &tile_row_alone<sim::WideAvx2>; }
}  // namespace pond::bench
