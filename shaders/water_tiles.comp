#version 460
// The tile bounds (shared/tile_bounds.h) from the columns' bounds the normals' tile variant wrote
// (water_normals.comp, POND_NORMALS_TILES): one invocation per tile widens the bounds of the
// tile's columns [16a, min(16a + 16, cols - 1)] over its tile row and makes its zeros +0. Min and
// max are exact and the zeros canonical, so the order does not matter: these are the bits of
// sim::compute_tile_bounds. Only compares and selects: no subgroup or shared memory, so any
// Vulkan 1.3 device runs it. The columns are read through an RGBA32F texel-buffer view, two texels
// a column: on llvmpipe a fetch is a gather (an SSBO load with a per-invocation address is a loop
// over the lanes), so a column is two fetches of four floats each.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require

#include "shared/tile_bounds.h"
#include "shared/water_gpu.h"

spirv_execution_mode(capabilities = [4466], 4461, 32);  // SignedZeroInfNanPreserve: NaN compares
#ifdef POND_DENORM_PRESERVE  // the variant for devices with shaderDenormPreserveFloat32 (float_policy.h)
spirv_execution_mode(capabilities = [4464], 4459, 32);  // DenormPreserve, 32-bit floats
#endif

layout(local_size_x = POND_TILES_LOCAL_X, local_size_y = 1, local_size_z = 1) in;

layout(set = 0, binding = POND_TILES_BINDING_COLUMNS) uniform samplerBuffer columns;  // RGBA32F: 2 texels a column
layout(std430, set = 0, binding = POND_TILES_BINDING_BOUNDS) restrict writeonly buffer Bounds {
  TileBounds bounds[];
};
layout(push_constant) uniform Push { TilesPush p; };

void main() {
  const uint t = gl_GlobalInvocationID.x;
  if (t >= p.tiles) return;
  const uint b = t / p.tiles_x, a = t - b * p.tiles_x;
  const float inf = uintBitsToFloat(0x7f800000u), minus_inf = uintBitsToFloat(0xff800000u);
  TileBounds tile = TileBounds(inf, inf, inf, minus_inf, minus_inf, minus_inf);
  const uint j0 = a * uint(POND_TILE_CELLS), j1 = min(j0 + uint(POND_TILE_CELLS), p.cols - 1u);
  for (uint j = j0; j <= j1; ++j) {
    const int k = int(POND_TILE_COLUMN_TEXELS * (b * p.cols + j));
    const vec3 lo = texelFetch(columns, k).xyz, hi = texelFetch(columns, k + 1).xyz;
    tile = bounds_widened(tile, TileBounds(lo.x, lo.y, lo.z, hi.x, hi.y, hi.z));
  }
  bounds[t] = bounds_canonical(tile);
}
