#version 460
// Caustics (shared/caustics.h): per corner of the floor map's texels, the surface point whose
// refracted sun ray lands there and the area ratio of the refracted grid of rays at that point: the
// floor's sunlight relative to calm water. One dispatch; a workgroup, in three steps between
// barriers, traces the rays around its texels into shared memory, takes their gradients, computes
// the light at its texels' corners; then each invocation writes its texel's four corners.
#extension GL_GOOGLE_include_directive : require

#include "shared/caustics.h"

layout(local_size_x = POND_CAUSTICS_LOCAL, local_size_y = POND_CAUSTICS_LOCAL, local_size_z = 1) in;

layout(set = 0, binding = POND_CAUSTICS_BINDING_STATE) uniform samplerBuffer state;
layout(set = 0, binding = POND_CAUSTICS_BINDING_NORMALS) uniform samplerBuffer normals;
layout(set = 0, binding = POND_CAUSTICS_BINDING_MAP, rgba8) uniform restrict writeonly image2D map;
layout(push_constant) uniform Push { CausticsPush p; };

// The rays of the workgroup's texels' cells with a ring of one more around them (for the gradients):
// POND_CAUSTICS_LOCAL texels' corners lie in at most POND_CAUSTICS_LOCAL + 1 cells across, whose
// corners are POND_CAUSTICS_TILE - 2 rays across. `tile`: each ray's offset d; `grad`: its gradient
// (d/ds.x, d/ds.y), by central differences over the neighbouring rays.
shared vec2 tile[POND_CAUSTICS_TILE * POND_CAUSTICS_TILE];
shared vec4 grad[POND_CAUSTICS_TILE * POND_CAUSTICS_TILE];
// The light at the workgroup's texels' corners (each computed once, shared by up to four texels).
#define CORNERS (POND_CAUSTICS_LOCAL + 1)
shared float corner[CORNERS * CORNERS];

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

// The light at q (in units of the rays' spacing) from the tile, whose ray (1, 1) is `origin`. The
// ray landing on q starts at the s with s + d(s) = q: one Newton step from s = q (the waves' d is a
// fraction of a cell), s = q - J^-1 d(q), with J = I + grad d the Jacobian of the map s -> s + d(s),
// d and grad d bilinear between the rays of q's cell (so J is continuous: no seams along the
// cells). A patch of surface of area A lights A |det J| of floor, so the light there is 1 / |det J|
// of calm water's, J taken at s (on the same bilinear patch, continued past the cell's edge if s
// lies beyond it).
float light_at(vec2 q, uvec2 origin, vec2 last_cell) {
  const vec2 cell = clamp(floor(q), vec2(0.0), last_cell);
  vec2 f = q - cell;
  const uint i = (uint(cell.y) - origin.y + 1u) * POND_CAUSTICS_TILE + (uint(cell.x) - origin.x + 1u);
  const uint i10 = i + 1u, i01 = i + POND_CAUSTICS_TILE, i11 = i01 + 1u;
  const vec2 dq = mix(mix(tile[i], tile[i10], f.x), mix(tile[i01], tile[i11], f.x), f.y);
  vec4 g = mix(mix(grad[i], grad[i10], f.x), mix(grad[i01], grad[i11], f.x), f.y);  // (d/ds.x, d/ds.y)
  const float det_q = (1.0 + g.x) * (1.0 + g.w) - g.y * g.z;
  const float safe = (det_q < 0.0 ? -1.0 : 1.0) * max(abs(det_q), 0.05);  // J is near singular at a focus
  const vec2 step = clamp(vec2((1.0 + g.w) * dq.x - g.z * dq.y, (1.0 + g.x) * dq.y - g.y * dq.x) / safe,
                          vec2(-1.0), vec2(1.0));
  f -= step;
  g = mix(mix(grad[i], grad[i10], f.x), mix(grad[i01], grad[i11], f.x), f.y);
  const float det = (1.0 + g.x) * (1.0 + g.w) - g.y * g.z;
  const float focus = 1.0 / max(abs(det), 1.0 / p.light.w);
  return (1.0 + p.light.z * (focus - 1.0)) * kCausticsUnit;
}

void main() {
  // In units of the rays' spacing (the Jacobian is the same in any unit): q, (column, row).
  const uvec2 rays = p.map.zw;
  const vec2 last_cell = vec2(rays) - vec2(2.0);
  const vec2 texel_size = (vec2(rays) - vec2(1.0)) / vec2(p.map.xy);
  const uvec2 texel = gl_GlobalInvocationID.xy;

  // 1. The tile's rays, from one before the cell of the workgroup's first texel's corner on.
  const uvec2 origin = uvec2(min(floor(vec2(gl_WorkGroupID.xy * POND_CAUSTICS_LOCAL) * texel_size), last_cell));
  const uint tile_size = POND_CAUSTICS_TILE * POND_CAUSTICS_TILE, group = POND_CAUSTICS_LOCAL * POND_CAUSTICS_LOCAL;
  for (uint k = gl_LocalInvocationIndex; k < tile_size; k += group) {
    const ivec2 at = ivec2(origin) - 1 + ivec2(k % POND_CAUSTICS_TILE, k / POND_CAUSTICS_TILE);
    tile[k] = ray_offset(uvec2(clamp(at, ivec2(0), ivec2(rays) - 1)));
  }
  barrier();
  // 2. Their gradients (one-sided at the pool's edge; the tile's own edge is never read).
  for (uint k = gl_LocalInvocationIndex; k < tile_size; k += group) {
    const ivec2 t = ivec2(k % POND_CAUSTICS_TILE, k / POND_CAUSTICS_TILE);
    const ivec2 at = ivec2(origin) - 1 + t, last = ivec2(rays) - 1;
    const ivec2 lo = max(t - 1, ivec2(0)), hi = min(t + 1, ivec2(POND_CAUSTICS_TILE - 1));
    const vec2 span = vec2(min(at + 1, last) - max(at - 1, ivec2(0)));  // rays apart, at the pool's edge 1
    const int row = t.y * POND_CAUSTICS_TILE;
    grad[k] = vec4((tile[row + hi.x] - tile[row + lo.x]) / max(span.x, 1.0),
                   (tile[hi.y * POND_CAUSTICS_TILE + t.x] - tile[lo.y * POND_CAUSTICS_TILE + t.x]) / max(span.y, 1.0));
  }
  barrier();
  // 3. The light at the workgroup's texels' corners.
  for (uint k = gl_LocalInvocationIndex; k < CORNERS * CORNERS; k += group) {
    const uvec2 at = gl_WorkGroupID.xy * POND_CAUSTICS_LOCAL + uvec2(k % CORNERS, k / CORNERS);
    corner[k] = light_at(vec2(at) * texel_size, origin, last_cell);
  }
  barrier();
  if (texel.x >= p.map.x || texel.y >= p.map.y) return;

  // 4. Each texel's four (shared/caustics.h: the water interpolates them).
  const uint c = gl_LocalInvocationID.y * CORNERS + gl_LocalInvocationID.x;
  imageStore(map, ivec2(texel), vec4(corner[c], corner[c + 1u], corner[c + CORNERS], corner[c + CORNERS + 1u]));
}
