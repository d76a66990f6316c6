#pragma once
// One tile row of the CPU step's tile bounds outside the step (BM_TileRowAlone, bench_solver.cpp):
// sim/tile_kernel.h's emit_tile_rows called at the rows where the step calls it, over new
// displacements already written, so its cost can be set against the floor of its min and max
// instructions without the step around it. One function per bounds table (tile_row_*.cpp).
#include "sim/step_view.h"
#include "sim/tile_bounds.h"

namespace pond::bench {

// The column passes over a tile row's 16 rows, the flush after its border row, or both.
enum class TileRowPart { pass, flush, both };

// Rows [0, 16] of `view` (rows 0-15 a tile row, row 16 its border) in columns [0, view.cols), one
// column block (view.cols <= kBlockCols), into `sink` (tile row 0 of `grid`).
using TileRowFn = void (*)(const sim::StepView& view, const sim::TileGrid& grid, TileRowPart part, sim::TileSink& sink);

TileRowFn tile_row_sse2();    // the scalar and SSE2 backends' table
TileRowFn tile_row_avx2();
TileRowFn tile_row_avx512();

}  // namespace pond::bench
