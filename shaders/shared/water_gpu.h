// Every CPU<->GPU layout of the water compute passes, declared once: the shaders include this file
// as GLSL, the C++ GPU solver as C++ (src/gpu/water_layout.h adds the static_asserts).
//
// Buffers (all std430, 32-bit words):
//  - state: structure of arrays, six arrays of `stride` floats one after the other:
//      ux at [0], uy at [stride], uz at [2*stride], vx at [3*stride], vy at [4*stride], vz at [5*stride]
//    node (row, col) at n = row * pitch + col, pitch = cols rounded up to 4 (gpu/water_layout.h
//    row_pitch: rows start 16-byte aligned); the pitch - cols padding nodes of a row are fixed
//    nodes at rest that no real node has as a neighbour. Grid units (world / spacing), u the displacement from the rest
//    position (j, 0, i), as sim::WaterState. Two of them
//    (ping-pong): a substep reads one and writes the other.
//  - kinds: the node kinds (kNodeFree / kNodeVertical / kNodeFixed) packed four per uint, node n
//    (with the pitch, as the state; padding kNodeFixed) in byte n % 4 of word n / 4 (little end
//    first), so the mask costs a quarter of a load per node.
//  - perturbations: PerturbEntry[] of every tabulated perturbation of the model, one after the
//    other; node = row * pitch + col, as the state.
//  - normals: one vec4 per node (nx, ny, nz, 0), compact: node row * cols + col, the LOD's index
//    buffer's numbering, which the water vertex shader reads them by.
//  - tile columns and tile bounds (only while tracked): shared/tile_bounds.h's TileBounds, 24 bytes.
#ifndef POND_WATER_GPU_H
#define POND_WATER_GPU_H

#include "shared/exact_math.h"

// Macros, not constants: GLSL needs literals in layout(local_size_x = ...) and
// layout(constant_id = ...). The C++ side reads the same macros to derive group counts.
#define POND_STEP_LOCAL_X 64       // default local size of water_step.comp; the solver sets it (below)
#define POND_STEP_LOCAL_X_MAX 256  // most invocations per workgroup of water_step.comp: a 1024-wide row
                                   // in the quad path (see water_step.comp); a multiple of 8
#define POND_STEP_ROWS_PER_INVOCATION 16  // each invocation walks a strip of this many rows
#define POND_PERTURB_LOCAL_X 64    // table entries per workgroup of water_perturb.comp
#define POND_NORMALS_LOCAL_X 64    // default local size of water_normals.comp; the solver sets it (below)
#define POND_NORMALS_LOCAL_X_MAX 256         // most invocations (columns) per workgroup of water_normals.comp
#define POND_NORMALS_ROWS_PER_INVOCATION 16  // each invocation of water_normals.comp walks this many rows
#define POND_SPEC_FAST_MATH 0      // specialization constant: bool, true = fast math
#define POND_SPEC_RSQRT_STEPS 1    // specialization constant: int, Newton steps of exact rsqrt
#define POND_SPEC_STEP_LOCAL_X 3   // specialization constant: water_step.comp's local_size_x
#define POND_SPEC_NORMALS_LOCAL_X 4  // specialization constant: water_normals.comp's local_size_x
#define POND_SPEC_PADDED_ROWS 5    // specialization constant: bool, the state's rows end in padding (pitch > cols)
#define POND_SPEC_TRACK_REACH 6    // specialization constant: bool, keep the reach (scenes with bodies)

// Bindings of water_step.comp: texel-buffer views of the state and the kinds (see the buffer notes
// above; the buffers are the same, only the views differ).
#define POND_STEP_BINDING_SRC1 0    // uniform texel buffer, R32_SFLOAT view of the source state
#define POND_STEP_BINDING_SRC4 1    // uniform texel buffer, R32G32B32A32_SFLOAT view of the source state
#define POND_STEP_BINDING_DST4 2    // storage buffer: the destination state as vec4[] (4 floats per element)
#define POND_STEP_BINDING_KINDS4 3  // uniform texel buffer, R8G8B8A8_UINT view (nodes 4t..4t+3 = texel t)
#define POND_STEP_BINDING_REACH 4   // storage buffer: uint, the float bits of the largest |ux|, |uz| written
                                    // (atomic max; with POND_SPEC_TRACK_REACH; shared/bodies.h step 2)
#define POND_STEP_BINDINGS 5

// Bindings of water_normals.comp.
#define POND_NORMALS_BINDING_STATE 0    // uniform texel buffer, R32_SFLOAT view of the state
#define POND_NORMALS_BINDING_NORMALS 1  // storage buffer: the normals, vec4[]
#define POND_NORMALS_BINDINGS 2
// The normals' tile variant (POND_NORMALS_TILES, shared/tile_bounds.h; on request only) also has:
#define POND_NORMALS_BINDING_TILE_COLUMNS 2  // storage buffer: vec4[], column j's bounds over tile row
                                             // b's nodes at texels 2 (b * cols + j) (least x, y, z, 0)
                                             // and the next (greatest x, y, z, 0)
#define POND_TILE_COLUMN_TEXELS 2            // RGBA32F texels a column's bounds take
#define POND_NORMALS_TILES_BINDINGS 3

// Bindings of water_tiles.comp: the tile columns above in, the tile bounds out (TileBounds[],
// tile (a, b) at b * tiles_x + a).
#define POND_TILES_BINDING_COLUMNS 0  // uniform texel buffer, R32G32B32A32_SFLOAT view of the tile columns
#define POND_TILES_BINDING_BOUNDS 1   // storage buffer: TileBounds[]
#define POND_TILES_BINDINGS 2
#define POND_TILES_LOCAL_X 64  // tiles per workgroup of water_tiles.comp

// Bindings of water_gather.comp (gpu/displacement_readback.h): runs of the state's ux | uy | uz
// packed for the host.
#define POND_GATHER_BINDING_STATE 0   // storage buffer: the state, as 32-bit words
#define POND_GATHER_BINDING_RUNS 1    // storage buffer: GatherRun[]
#define POND_GATHER_BINDING_PACKED 2  // storage buffer: component by component, runs in order
#define POND_GATHER_BINDINGS 3
#define POND_GATHER_LOCAL_X 64  // nodes of a run per invocation round

#ifdef __cplusplus
#define POND_GPU_CONST inline constexpr
namespace pond::shared {
#else
#define POND_GPU_CONST const
#endif

// Push constants of water_step.comp: one substep.
struct StepPush {
  uint rows;
  uint cols;
  uint stride;     // floats between the component arrays of a state buffer
  uint pitch;      // nodes between two rows of a state buffer (cols rounded up to 4)
  float kc;        // StepConstants (sim/model.h), bit for bit
  float kd;
  float dt;
  float rest_edge;
  float rest_diag;
};

// One tabulated perturbation weight (sim::PerturbationTable, flattened).
struct PerturbEntry {
  uint node;
  float weight;
};

POND_GPU_CONST uint kPerturbVelocity = 0u;  // target: vy
POND_GPU_CONST uint kPerturbPosition = 1u;  // target: y
POND_GPU_CONST uint kPerturbAdd = 0u;       // mode: value + w
POND_GPU_CONST uint kPerturbSet = 1u;       // mode: w

// Push constants of water_perturb.comp: one perturbation = entries [first, first + count).
struct PerturbPush {
  uint first;
  uint count;
  uint stride;
  uint target;
  uint mode;
};

// Push constants of water_normals.comp.
struct NormalsPush {
  uint rows;
  uint cols;
  uint stride;
  uint pitch;  // nodes between two rows of the state (the normals are compact: row * cols + col)
};

// Push constants of water_tiles.comp.
struct TilesPush {
  uint cols;     // nodes along a row (the tile columns' row length)
  uint tiles_x;  // tiles along a row
  uint tiles;    // tiles_x * tiles_y
};

// One run of water_gather.comp: `nodes` nodes from state node `first`, to packed node `packed`.
struct GatherRun {
  uint first;
  uint nodes;
  uint packed;
  uint unused;
};

// Push constants of water_gather.comp.
struct GatherPush {
  uint runs;
  uint stride;      // words between the state's components
  uint run_nodes;   // nodes of all runs: words between the packed components
};

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#undef POND_GPU_CONST
#endif
