#version 460
// Vertex normals of a state into the buffer the water vertex shader reads (one vec4 per node):
//   n = normalize((x[i+1][j] - x[i-1][j]) x (x[i][j+1] - x[i][j-1])),
// central differences, one-sided at the border, +y at rest. The same operations in the same order
// as sim::compute_normals (src/sim/normals.cpp), all `precise`, normalized with the exact Newton
// rsqrt, so the GPU normals equal the CPU's bit for bit.
//
// Speed on lavapipe (see the top of water_step.comp): the state is read through an R32F
// texel-buffer view (a straight-line gather per fetch; an SSBO load with a per-invocation address
// is a loop over the 8 lanes), and one invocation walks one column down a strip of
// POND_NORMALS_ROWS_PER_INVOCATION rows, keeping the column's rows i-1, i, i+1 in a sliding
// window: 9 fetches per node (the row above and the two side neighbours) instead of 12. The lanes
// of a group are consecutive columns, so each gather reads one contiguous run. The workgroup
// width is a specialization constant: the solver spans the row in as few, as evenly filled groups
// as it can (257 columns: 2 x 136, not 5 x 64 with one column in the last).
//
// The tile variant (POND_NORMALS_TILES, only while the tile bounds are tracked: gpu/tile_kernels.h)
// also widens each column's bounds over its strip, which is a tile row, plus the row below it that
// the window already holds (the tile's shared border): water_tiles.comp merges them into tiles.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require

#include "shared/exact_math.h"
#include "shared/tile_bounds.h"
#include "shared/water_gpu.h"

spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve, 32-bit floats
#ifdef POND_DENORM_PRESERVE  // the variant for devices with shaderDenormPreserveFloat32 (float_policy.h)
spirv_execution_mode(capabilities = [4464], 4459, 32);  // DenormPreserve, 32-bit floats
#endif

layout(local_size_x = POND_NORMALS_LOCAL_X, local_size_y = 1, local_size_z = 1) in;
layout(local_size_x_id = POND_SPEC_NORMALS_LOCAL_X) in;

layout(set = 0, binding = POND_NORMALS_BINDING_STATE) uniform samplerBuffer state;  // R32F: float n
layout(std430, set = 0, binding = POND_NORMALS_BINDING_NORMALS) restrict writeonly buffer Normals { vec4 normals[]; };
layout(push_constant) uniform Push { NormalsPush p; };
#ifdef POND_NORMALS_TILES
#if POND_NORMALS_ROWS_PER_INVOCATION != POND_TILE_CELLS
#error "a strip of the normals must be a tile row"
#endif
layout(std430, set = 0, binding = POND_NORMALS_BINDING_TILE_COLUMNS) restrict writeonly buffer TileColumns {
  vec4 tile_columns[];  // POND_TILE_COLUMN_TEXELS a column (water_gpu.h): two vector stores
};
TileBounds node_bounds(vec3 u) { return TileBounds(u.x, u.y, u.z, u.x, u.y, u.z); }
#endif

vec3 load_u(uint n) {
  return vec3(texelFetch(state, int(n)).x, texelFetch(state, int(p.stride + n)).x,
              texelFetch(state, int(2u * p.stride + n)).x);
}

void main() {
  const uint j = gl_GlobalInvocationID.x;
  const uint first = gl_GlobalInvocationID.y * POND_NORMALS_ROWS_PER_INVOCATION;
  if (j >= p.cols || first >= p.rows) return;
  const uint last = min(first + POND_NORMALS_ROWS_PER_INVOCATION, p.rows);
  const uint C = p.cols, P = p.pitch;  // the state's rows are P nodes apart, the normals' C
  const uint j1 = min(j + 1u, C - 1u), j0 = j > 0u ? j - 1u : 0u;
  // The window: rows i0 = max(i-1, 0) and i of column j (i1 = min(i+1, rows-1) is fetched per row).
  vec3 down = load_u((first > 0u ? first - 1u : 0u) * P + j);
  vec3 mid = load_u(first * P + j);
#ifdef POND_NORMALS_TILES
  const float inf = uintBitsToFloat(0x7f800000u), minus_inf = uintBitsToFloat(0xff800000u);
  TileBounds column = TileBounds(inf, inf, inf, minus_inf, minus_inf, minus_inf);
#endif
  for (uint i = first; i < last; ++i) {
#ifdef POND_NORMALS_TILES
    column = bounds_widened(column, node_bounds(mid));  // row i
#endif
    const uint i1 = min(i + 1u, p.rows - 1u), i0 = i > 0u ? i - 1u : 0u;
    const vec3 up = i1 == i ? mid : load_u(i1 * P + j);
    // Position differences = displacement differences + the rest offset (i1 - i0 or j1 - j0),
    // added even when it is 0, as the CPU does.
    precise vec3 a = up - down;
    a.z = a.z + float(i1 - i0);
    precise vec3 b = load_u(i * P + j1) - load_u(i * P + j0);
    b.x = b.x + float(j1 - j0);
    precise float cx = a.y * b.z - a.z * b.y;
    precise float cy = a.z * b.x - a.x * b.z;
    precise float cz = a.x * b.y - a.y * b.x;
    precise float l2 = (cx * cx + cy * cy) + cz * cz;
    const bool ok = l2 > 0.0;
    precise float r = ok ? rsqrt_exact(l2, kRsqrtStepsExact) : 0.0;
    precise vec3 nrm = vec3(cx * r, ok ? cy * r : 1.0, cz * r);
    normals[i * C + j] = vec4(nrm, 0.0);
    down = mid;
    mid = up;
  }
#ifdef POND_NORMALS_TILES
  // mid is row min(last, rows - 1): the next strip's first row, the tile's border. A grid of
  // 16k + 1 rows has one strip more than tile rows, its one row the last tile row's border.
  if (last < p.rows) column = bounds_widened(column, node_bounds(mid));
  if (gl_GlobalInvocationID.y < tiles_along(p.rows)) {
    const uint at = POND_TILE_COLUMN_TEXELS * (gl_GlobalInvocationID.y * C + j);
    tile_columns[at] = vec4(column.min_x, column.min_y, column.min_z, 0.0);
    tile_columns[at + 1u] = vec4(column.max_x, column.max_y, column.max_z, 0.0);
  }
#endif
}
