// The caustics pass's CPU<->GPU layouts, declared once: included by shaders/caustics.comp and
// water.frag as GLSL and by src/render/caustics_pass.h as C++ (static_asserts there).
//
// The map: the pool floor's sunlight relative to calm water (1 = as calm water lights it, stored as
// kCausticsUnit), over the pool [0, cols - 1] x [0, rows - 1] (grid units, x along the columns).
// Texel (x, y) covers [x, x + 1] (cols - 1) / width by [y, y + 1] (rows - 1) / height and holds the
// light at its four corners, rgba = (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1): one nearest
// fetch gives the water all it needs to interpolate bilinearly (a bilinear fetch costs llvmpipe
// several times more). Its coordinates are the floor point shifted back by the calm surface's
// refraction offset (the place where calm water's sun ray through rest node (j, i) meets the floor
// is (j, i) on the map), so calm water maps every cell onto its own texels and the map is 1
// everywhere, up to the pool's edges.
//
// One compute dispatch a frame (render/caustics_pass.h, shaders/caustics.comp), over a grid of rays
// at most kCausticsRays cells across (every node of a grid up to that size, every second node of a
// 257 x 257 one, ...):
//  - per ray: the sun's ray refracted through the water surface at the nearest node (its displaced
//    position and normal) and followed to the floor plane; d = its landing point's offset from the
//    calm one (in units of the rays' spacing);
//  - per texel corner q: the surface point s whose ray lands there, by one Newton step of s + d(s) = q
//    (d and its gradient, by central differences at the rays, bilinear between the rays), and the
//    area ratio there, 1 / |det(I + grad d)|: how much the
//    surface focuses (> 1) or spreads (< 1) the light falling on it. Only the direct sun's share of
//    the floor's light is scaled.
#ifndef POND_CAUSTICS_H
#define POND_CAUSTICS_H

#ifdef __cplusplus
#include "shared/water_render.h"
namespace pond::shared::caustics {
using water_render::uvec4;
using water_render::vec4;
#define POND_CAUSTICS_CONST inline constexpr
#else
#define POND_CAUSTICS_CONST const
#endif

#define POND_CAUSTICS_LOCAL 8  // caustics.comp's workgroups: 8 x 8 texels
#define POND_CAUSTICS_TILE 12  // the rays a workgroup traces: 12 x 12 (its texels' cells' corners and one more)

// Bindings (set 0). Texel buffers for the reads: on llvmpipe a texel fetch is a gather, an SSBO load
// a loop over the lanes.
#define POND_CAUSTICS_BINDING_STATE 0    // uniform texel buffer, R32_SFLOAT view of the water state
                                         // (water_render.h binding 1)
#define POND_CAUSTICS_BINDING_NORMALS 1  // uniform texel buffer, R32G32B32A32_SFLOAT view of the
                                         // normals (vec4 per node, compact)
#define POND_CAUSTICS_BINDING_MAP 2      // storage image, R8G8B8A8_UNORM: the map (kCausticsUnit)
#define POND_CAUSTICS_BINDINGS 3

// The map's binding in the water's set (shared/water_render.h: the passes' follow the set's own), a
// combined image sampler read by water.frag where POND_SPEC_CAUSTICS is on.
#define POND_CAUSTICS_WATER_BINDING 6

// Push constants.
struct CausticsPush {
  vec4 sun;     // xyz: unit direction toward the sun; w: the floor's depth below rest (grid units)
  vec4 light;   // xy: the calm surface's offset of the ray's landing point (grid units);
                // z: the direct sun's share of the floor's light; w: the brightest a texel gets
  uvec4 grid;   // rows, cols, the state's stride (floats) and pitch (nodes)
  uvec4 map;    // width, height (texels); z, w: the rays' grid, columns and rows
  vec4 coarse;  // xy: grid units between the rays' columns and rows; zw: 0
};

// Water's index of refraction (air -> water: 1 / kWaterIor), as water.frag's view ray uses.
POND_CAUSTICS_CONST float kWaterIor = 1.33f;
// The floor's light is kFloorAmbient of the sky's plus (1 - kFloorAmbient) * sun.y of the sun's
// (water.vert's POND_WATER_FLAT_GROUND): the caustics scale the second part. A clear sky gives
// about 28 % of the light on a level surface when the sun is 22 degrees up (the default sun) and
// less higher up, so the sky's part is 0.13 and the sun's 0.87 sun.y (a direct share of 0.72 at
// the default sun; docs/picture.md).
POND_CAUSTICS_CONST float kFloorAmbient = 0.13f;
// The map holds light * kCausticsUnit in an R8G8B8A8_UNORM image (a storage format every device
// has, and a fast one for llvmpipe to sample): light 1 is level 32 exactly, the brightest 255/32
// (a focus of kMaxFocus with the direct share at 1 is 8), steps of 1/32.
POND_CAUSTICS_CONST float kCausticsUnit = 32.0f / 255.0f;
POND_CAUSTICS_CONST float kCausticsDecode = 255.0f / 32.0f;
// The rays' grid has at most kCausticsRays cells across, and the map whole texels per cell of it,
// as many as fit in kCausticsTexels (at least one): the pass's cost grows with both (docs/perf.md).
// A 257 x 257 grid: rays on every fourth node, 64 x 64 texels; 50 x 50: every node, 49 x 49.
POND_CAUSTICS_CONST int kCausticsRays = 64;
POND_CAUSTICS_CONST int kCausticsTexels = 64;
// 1 / |det| where the surface focuses the light to a line (det -> 0) is clamped to this.
POND_CAUSTICS_CONST float kMaxFocus = 8.0f;

#ifdef __cplusplus
}  // namespace pond::shared::caustics
#endif
#undef POND_CAUSTICS_CONST
#endif
