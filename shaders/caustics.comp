#version 460
// Caustics (shared/caustics.h): per texel of the floor's map, the surface point whose refracted sun
// ray lands there and the area ratio of the refracted grid of rays at that point: the floor's
// sunlight relative to calm water. One dispatch: a workgroup first traces the rays of the cells
// its texels lie in into shared memory, then each invocation shades its texel from them.
#extension GL_GOOGLE_include_directive : require

#include "shared/caustics.h"

layout(local_size_x = POND_CAUSTICS_LOCAL, local_size_y = POND_CAUSTICS_LOCAL, local_size_z = 1) in;

layout(set = 0, binding = POND_CAUSTICS_BINDING_STATE) uniform samplerBuffer state;
layout(set = 0, binding = POND_CAUSTICS_BINDING_NORMALS) uniform samplerBuffer normals;
layout(set = 0, binding = POND_CAUSTICS_BINDING_MAP, rgba8) uniform restrict writeonly image2D map;
layout(push_constant) uniform Push { CausticsPush p; };

// The rays of the workgroup's cells: POND_CAUSTICS_LOCAL texels span at most that many cells, so
// their cells' corners are POND_CAUSTICS_TILE rays across.
shared vec2 tile[POND_CAUSTICS_TILE * POND_CAUSTICS_TILE];

// Where the sun's ray refracted at ray (column, row) lands on the floor relative to where calm water
// lands it, in units of the rays' spacing. The ray takes the nearest node's surface (the same node
// where the spacing is whole; else up to half a cell away, which calm water cannot tell).
vec2 ray_offset(uvec2 ray) {
  const uvec2 node = min(uvec2(vec2(ray) * p.coarse.xy + 0.5), uvec2(p.grid.y - 1u, p.grid.x - 1u));
  const int m = int(node.y * p.grid.w + node.x), stride = int(p.grid.z);
  const vec3 u = vec3(texelFetch(state, m).x, texelFetch(state, stride + m).x, texelFetch(state, 2 * stride + m).x);
  const vec3 t = refract(-p.sun.xyz, texelFetch(normals, int(node.y * p.grid.y + node.x)).xyz, 1.0 / kWaterIor);
  // Down to the floor, sun.w below rest, from the node's height; a ray that does not go down (a
  // folded crest's normal) is taken as nearly horizontal rather than divided by zero.
  const float along = max(u.y + p.sun.w, 0.0) / max(-t.y, 0.05);
  return (u.xz + t.xz * along - p.light.xy) / p.coarse.xy;
}

void main() {
  // In units of the rays' spacing (the Jacobian is the same in any unit): q, (column, row).
  const uvec2 rays = p.map.zw;
  const vec2 last_cell = vec2(rays) - vec2(2.0);
  const vec2 texel_size = (vec2(rays) - vec2(1.0)) / vec2(p.map.xy);
  const uvec2 texel = gl_GlobalInvocationID.xy;
  const vec2 q = (vec2(texel) + 0.5) * texel_size;

  // 1. The tile's rays, from the cell of the workgroup's first texel on.
  const uvec2 origin = uvec2(min(floor((vec2(gl_WorkGroupID.xy * POND_CAUSTICS_LOCAL) + 0.5) * texel_size), last_cell));
  for (uint k = gl_LocalInvocationIndex; k < POND_CAUSTICS_TILE * POND_CAUSTICS_TILE;
       k += POND_CAUSTICS_LOCAL * POND_CAUSTICS_LOCAL) {
    const uvec2 at = origin + uvec2(k % POND_CAUSTICS_TILE, k / POND_CAUSTICS_TILE);
    tile[k] = ray_offset(min(at, rays - 1u));
  }
  barrier();
  if (texel.x >= p.map.x || texel.y >= p.map.y) return;

  // 2. The ray landing on q starts at the s with s + d(s) = q, d bilinear between the rays of q's
  // cell: one Newton step from s = q (the waves' d is a fraction of a cell), s = q - J^-1 d(q), with
  // J = I + grad d the Jacobian of the map s -> s + d(s). A patch of surface of area A lights
  // A |det J| of floor, so the light there is 1 / |det J| of calm water's, det J taken at s (on the
  // same bilinear patch, continued past the cell's edge if s lies beyond it).
  const vec2 cell = clamp(floor(q), vec2(0.0), last_cell);
  const vec2 f = q - cell;
  const uint i = (uint(cell.y) - origin.y) * POND_CAUSTICS_TILE + (uint(cell.x) - origin.x);
  const vec2 d00 = tile[i], d10 = tile[i + 1u], d01 = tile[i + POND_CAUSTICS_TILE], d11 = tile[i + POND_CAUSTICS_TILE + 1u];
  const vec2 e = d00 - d10 - d01 + d11;  // the patch's twist: grad d changes by e per unit
  vec2 dx = d10 - d00 + e * f.y;         // d/ds.x at q
  vec2 dy = d01 - d00 + e * f.x;         // d/ds.y at q
  const vec2 dq = d00 + (d10 - d00) * f.x + dy * f.y;
  const float det_q = (1.0 + dx.x) * (1.0 + dy.y) - dx.y * dy.x;
  const float safe = (det_q < 0.0 ? -1.0 : 1.0) * max(abs(det_q), 0.05);  // J is near singular at a focus
  const vec2 step = clamp(vec2((1.0 + dy.y) * dq.x - dy.x * dq.y, (1.0 + dx.x) * dq.y - dx.y * dq.x) / safe,
                          vec2(-1.0), vec2(1.0));
  dx -= e * step.y;  // at s = q - step
  dy -= e * step.x;
  const float det = (1.0 + dx.x) * (1.0 + dy.y) - dx.y * dy.x;
  const float focus = 1.0 / max(abs(det), 1.0 / p.light.w);
  imageStore(map, ivec2(texel), vec4((1.0 + p.light.z * (focus - 1.0)) * kCausticsUnit));
}
