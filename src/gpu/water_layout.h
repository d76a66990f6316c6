#pragma once
// The C++ view of shaders/shared/water_gpu.h: the structs are declared there once, for GLSL and
// C++; this header pins their std430 / push-constant layout so a change on one side cannot
// silently disagree with the other.
#include <cstddef>

#include "shared/tile_bounds.h"
#include "shared/water_gpu.h"

namespace pond::gpu {

using shared::GatherPush;
using shared::GatherRun;
using shared::NormalsPush;
using shared::PerturbEntry;
using shared::PerturbPush;
using shared::StepPush;
using shared::TileBounds;
using shared::TilesPush;

static_assert(sizeof(StepPush) == 36);
static_assert(offsetof(StepPush, rows) == 0 && offsetof(StepPush, cols) == 4 && offsetof(StepPush, stride) == 8 &&
              offsetof(StepPush, pitch) == 12);
static_assert(offsetof(StepPush, kc) == 16 && offsetof(StepPush, kd) == 20 && offsetof(StepPush, dt) == 24);
static_assert(offsetof(StepPush, rest_edge) == 28 && offsetof(StepPush, rest_diag) == 32);
static_assert(sizeof(PerturbEntry) == 8 && offsetof(PerturbEntry, weight) == 4);
static_assert(sizeof(PerturbPush) == 20 && offsetof(PerturbPush, first) == 0 && offsetof(PerturbPush, count) == 4 &&
              offsetof(PerturbPush, stride) == 8 && offsetof(PerturbPush, target) == 12 &&
              offsetof(PerturbPush, mode) == 16);
static_assert(sizeof(NormalsPush) == 16 && offsetof(NormalsPush, stride) == 8 && offsetof(NormalsPush, pitch) == 12);
static_assert(sizeof(TilesPush) == 12 && offsetof(TilesPush, tiles_x) == 4 && offsetof(TilesPush, tiles) == 8);
static_assert(sizeof(TileBounds) == 24 && offsetof(TileBounds, min_y) == 4 && offsetof(TileBounds, max_x) == 12 &&
              offsetof(TileBounds, max_z) == 20);
// The normals' strip of rows is a tile row: their tile variant writes each column's bounds over it.
static_assert(POND_NORMALS_ROWS_PER_INVOCATION == POND_TILE_CELLS);

// Components of the state buffer (structure of arrays), in the order of the shared header.
enum StateComponent : unsigned { kUx = 0, kUy, kUz, kVx, kVy, kVz, kComponents };

// Nodes between two rows of the GPU state (the row pitch): the columns rounded up to 4, so every
// row starts 16-byte aligned and the step shader's quad path (4 columns per RGBA32F texel) works on
// every grid. Node (i, j) is at i * pitch + j; the padding columns j = cols .. pitch-1 are fixed
// nodes at rest (+0), never a neighbour of a real node (water_step.comp).
constexpr std::size_t row_pitch(std::size_t cols) { return (cols + 3) / 4 * 4; }

// Floats between the component arrays: the node count rounded up to 16 (64-byte aligned arrays).
// For the GPU solver's state, the node count with padding: rows * row_pitch(cols).
constexpr std::size_t state_stride(std::size_t nodes) { return (nodes + 15) / 16 * 16; }

static_assert(row_pitch(257) == 260 && row_pitch(256) == 256 && row_pitch(2) == 4);

}  // namespace pond::gpu
