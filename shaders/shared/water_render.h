// The water renderer's CPU<->GPU layouts, declared once: included by shaders/water.vert,
// water.frag, water_wire.frag, land.vert, land.frag as GLSL and by src/render/render_layout.h as C++
// (which pins sizes and offsets with static_asserts).
//
// Bindings of the one descriptor set every pass of the water renderer uses (set 0):
//   0: uniform WaterFrame (std140), per frame slot
//   1: storage buffer, the water state (structure of arrays, water_gpu.h): ux | uy | uz | ...,
//      each `stride` floats, node (i, j) at i * pitch + j, grid units, displacement from the rest
//      position (j, 0, i)
//   2: storage buffer, the normals: one vec4 per node, compact (node i * cols + j)
//   POND_RENDER_BINDINGS and up: what the passes whose output the water reads bind, each pass its
//      own (render/frame_pass.h: it adds the binding to the set's layout and writes it every frame,
//      its output or a stand-in); the set layout refuses a number taken twice. The layers' numbers
//      are here, as the land's shaders read the shadow map too; the caustics map's and the foam's
//      are in their own headers (shared/caustics.h, shared/foam.h):
//   3: combined image sampler, the planar reflection (render/reflection_pass.h), per frame slot;
//      read only by water_reflect.frag
//   4: combined image sampler with depth compare (sampler2DShadow), the sun's shadow map
//      (render/shadow_pass.h), per frame slot; read by the land and the water when
//      POND_SPEC_SHADOWS is on
//   5: combined image sampler, what lies under the surface (render/submerged_pass.h), per frame
//      slot; read by water.frag where POND_SPEC_SUBMERGED is on
// The water is drawn with vertex pulling: the index buffer holds node indices n = row * cols + col
// (the LOD builder's output as is), the vertex shader reads the normals at gl_VertexIndex and the
// state at its row * pitch + col.
// The land (shore, islands, pool rim) is an ordinary vertex buffer of LandVertex.
#ifndef POND_WATER_RENDER_H
#define POND_WATER_RENDER_H

#ifdef __cplusplus
#include <cstdint>
namespace pond::shared::water_render {
// Just enough of GLSL's types for the declarations below (std140: vec4 and mat4 are 16-aligned,
// which these plain arrays of floats reproduce as long as every member is a vec4 or a mat4).
using uint = std::uint32_t;
struct vec4 {
  float x = 0, y = 0, z = 0, w = 0;
};
struct uvec4 {
  uint x = 0, y = 0, z = 0, w = 0;
};
struct mat4 {
  float m[16] = {};  // column-major, as GLSL
};
#define POND_RENDER_CONST inline constexpr
#else
#define POND_RENDER_CONST const
#endif

#define POND_RENDER_BINDING_FRAME 0
#define POND_RENDER_BINDING_STATE 1
#define POND_RENDER_BINDING_NORMALS 2
#define POND_RENDER_BINDING_REFLECTION 3
#define POND_RENDER_BINDING_SHADOW 4
#define POND_RENDER_BINDING_SUBMERGED 5
#define POND_RENDER_BINDINGS 3  // the set's own (frame, state, normals); the passes' follow

// The fragment shaders take the frame's constants as flat varyings from their vertex shader, not
// from the uniform block: llvmpipe (Mesa 22.3) reads a uniform (or push constant) in a fragment
// shader as an 8-lane gather with a bounds check per lane and per float, because a batch of
// fragments may start with an inactive one and it cannot load once and broadcast; a flat input is
// read once per triangle (instruction counts: docs/perf.md). What depends on the frame alone is
// also computed there, once a vertex rather than once a pixel. Locations of water.vert ->
// water.frag:
#define POND_WATER_FLAT_EYE 2      // xyz: the camera; w: POND_FLAT_INV_SPACING
#define POND_WATER_FLAT_SUN 3      // xyz: WaterFrame::sun; w: POND_FLAT_FLOOR_DEPTH
#define POND_WATER_FLAT_SKY 4      // rgb: WaterFrame::sky.rgb (the zenith); a: POND_FLAT_CAUSTICS
#define POND_WATER_FLAT_WATER 5    // rgb: WaterFrame::water.rgb; a: POND_FLAT_CAUSTICS
#define POND_WATER_FLAT_GROUND 6   // rgb: WaterFrame::ground.rgb lit by the sun; a: POND_FLAT_CAUSTICS
#define POND_WATER_FLAT_HORIZON 7  // rgb: the sky's colour at the horizon; a: POND_FLAT_CAUSTICS
#define POND_WATER_FLAT_ABSORB 8   // the water's absorption per world unit (rgb)
#define POND_WATER_FLAT_POOL 9     // xy: the pool's far corner (cols - 1, rows - 1), grid units;
                                   // zw: POND_FLAT_CAUSTICS_SIZE
#define POND_WATER_FLAT_SCREEN 10  // WaterFrame::screen
#define POND_WATER_SHADOW 11       // (smooth) the surface point in the shadow map (shadow_sampling.h)
#define POND_WATER_FLAT_SHADOW_X 12  // WaterFrame::shadow's rows x, y, z (world -> shadow map)
#define POND_WATER_FLAT_SHADOW_Y 13
#define POND_WATER_FLAT_SHADOW_Z 14
#define POND_WATER_FLAT_SHADOW_SUN 15  // xyz: the sunlight's direction under the water; w: the floor's
                                       // light in shadow over its light in the sun
// The spare lanes of these varyings by name (each macro is the lanes themselves: no extra varying,
// no extra instruction). The caustics map's place rides in spare lanes because the locations above
// are all 16 that every device has (maxFragmentInputComponents is at least 64).
#define POND_FLAT_INV_SPACING(eye) ((eye).w)  // 1 / the grid spacing (grid units per world unit)
#define POND_FLAT_FLOOR_DEPTH(sun) ((sun).w)  // the pool floor's depth (POND_FRAME_FLOOR_DEPTH)
#define POND_FLAT_CAUSTICS(sky, water, ground, horizon) \
  vec4((sky).w, (water).w, (ground).w, (horizon).w)    // WaterFrame::caustics
#define POND_FLAT_CAUSTICS_SIZE(pool) ((pool).zw)    // WaterFrame::caustics_size.xy, as floats

// Fragment-shader specialization constant (bool), set by render/graphics_pipeline.cpp from the colour
// format: true when the target is UNORM and the shader must encode sRGB itself.
#define POND_SPEC_ENCODE_SRGB 0
// Fragment-shader specialization constant (bool): the land and the water sample the sun's shadow map
// (render/shadow_pass.h). Off, the shaders contain no shadow code at all.
#define POND_SPEC_SHADOWS 1
// Fragment-shader specialization constant (bool): water.frag lights the floor with the caustics map.
#define POND_SPEC_CAUSTICS 2
// Fragment-shader specialization constant (bool): water.frag shows the submerged layer
// (render/submerged_pass.h) where its refracted ray meets what the layer holds.
#define POND_SPEC_SUBMERGED 3

// Everything a frame's shaders need, one uniform block (std140), written per frame slot. Every
// member is a vec4 (or mat4), so the layout is the same in both languages; the lanes that hold
// something other than the member's name says are read and written through the POND_FRAME_*
// accessors below.
struct WaterFrame {
  mat4 view_proj;  // world -> clip, Vulkan conventions (y down, depth 0..1)
  vec4 eye;        // xyz: camera position (world); w: POND_FRAME_GRID_SPACING
  vec4 sun;        // xyz: unit direction toward the sun; w: a pass's lane (shared/foam.h)
  vec4 sky;        // rgb: sky colour at the zenith (linear); w: unused
  vec4 water;      // rgb: deep water colour (linear); w: unused
  vec4 ground;     // rgb: pool floor, shore and island colour (linear); w: unused
  vec4 pool;       // x: POND_FRAME_FLOOR_DEPTH; y: POND_FRAME_LAND_HEIGHT; zw: 0
  vec4 wire;       // rgb: LOD wireframe colour; a: its opacity
  uvec4 grid;      // x, y, z, w: POND_FRAME_ROWS, _COLS, _STATE_STRIDE, _STATE_PITCH
  // The sky's box (sky.vert): walls standing on the land's outer edge and a lid, from sky_lo.xyz
  // to sky_hi.xyz (world; w: 0).
  vec4 sky_lo;
  vec4 sky_hi;
  vec4 screen;  // xy: 1 / the target's size (pixels); z: the reflection's shift per unit of the
                // normal's xz tilt (in screen widths and heights); w: 0
  // The sun's shadow map (render/shadow_pass.h): world -> (u, v, depth), u and v in [0, 1] across
  // the map, depth in [0, 1] over the casters' range along the sunlight. Row 3 is (0, 0, 0, 1).
  mat4 shadow;
  vec4 shadow_sun;  // xyz: the sunlight's direction in the water (refracted, unit, pointing down);
                    // w: unused
  uvec4 caustics_size;  // xy: the caustics map's size (texels); zw: 0
  vec4 caustics;  // a world point p's place in the caustics map: uv = p.xz * xy + p.y * zw
                  // (render/caustics_pass.h caustics_lookup)
  vec4 absorption;  // rgb: the water's Beer-Lambert absorption per world unit of path; w: 0
};

// The packed lanes of a WaterFrame by name. Macros, so that one spelling serves both languages
// (GLSL has no member functions or references): each is the lane itself, an lvalue the C++ writer
// assigns and the shaders read, so the shaders compile to the same code as with the bare lane.
#define POND_FRAME_GRID_SPACING(frame) ((frame).eye.w)  // h: world units between nodes
#define POND_FRAME_FLOOR_DEPTH(frame) ((frame).pool.x)  // pool floor below the rest surface (world)
#define POND_FRAME_LAND_HEIGHT(frame) ((frame).pool.y)  // land above the rest surface (world)
#define POND_FRAME_ROWS(frame) ((frame).grid.x)         // nodes
#define POND_FRAME_COLS(frame) ((frame).grid.y)         // nodes
#define POND_FRAME_STATE_STRIDE(frame) ((frame).grid.z)  // floats between the state's arrays
#define POND_FRAME_STATE_PITCH(frame) ((frame).grid.w)   // nodes between the state's rows (cols
                                                         // where the state is compact)

// One vertex of the land mesh: position (world, w = 1) and normal (w = 0).
struct LandVertex {
  vec4 position;
  vec4 normal;
};

// How wet (darker) a wall looks at height y: clamp(kLandWetAtRest - y / land_height, 0, 1), 0 from
// kLandWetAtRest * land_height up, 1 from (kLandWetAtRest - 1) * land_height down. land.vert lights
// the land per vertex, which is exact where the light is linear across a triangle: the land's faces
// are flat, and build_land_mesh cuts every wall at these two heights, the kinks of the clamp.
POND_RENDER_CONST float kLandWetAtRest = 0.3f;

#ifdef __cplusplus
}  // namespace pond::shared::water_render
#endif
#undef POND_RENDER_CONST
#endif
