#pragma once
// tile_row_alone.h's functions for one backend's wide table W, compiled with its flags.
#include "tile_row_alone.h"
#include "sim/tile_kernel.h"

namespace pond::bench {

template <class W>
void tile_row_alone(const sim::StepView& view, const sim::TileGrid& grid, TileRowPart part, sim::TileSink& sink) {
  const int r1 = view.rows, passes = sim::pass_rows(view.cols);
  for (int i = 0; i <= sim::kTileCells; ++i) {
    sim::TileRowEvents events = sim::tile_row_events(i, r1, passes);
    if (part == TileRowPart::pass) events.ends_tile_row = false;
    if (part == TileRowPart::flush) events.ends_pass = false;
    if (events.any()) sim::emit_tile_rows<W>(view, grid, events, i, 0, 0, view.cols, sink);
  }
}

}  // namespace pond::bench
