// Built with the avx512 kernel's flags (bench/sim/CMakeLists.txt).
#include "tile_row_alone_impl.h"
#include "sim/wide_avx512.h"

namespace pond::bench {
TileRowFn tile_row_avx512() { return &tile_row_alone<sim::WideAvx512>; }
}  // namespace pond::bench
