#version 460
// The water surface, pulled straight from the solver's buffers: the index buffer holds node indices
// (the LOD builder's output), the state and normal buffers are the ones the compute passes (or the
// CPU solver) wrote this frame. No vertex attributes, no CPU copy of the vertex data.
#extension GL_GOOGLE_include_directive : require

#include "shared/caustics.h"
#include "shared/foam.h"
#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(std140, set = 0, binding = POND_RENDER_BINDING_FRAME) uniform Frame { WaterFrame f; };
layout(std430, set = 0, binding = POND_RENDER_BINDING_STATE) restrict readonly buffer State { float state[]; };
layout(std430, set = 0, binding = POND_RENDER_BINDING_NORMALS) restrict readonly buffer Normals { vec4 normals[]; };
layout(std430, set = 0, binding = POND_FOAM_WATER_BINDING) restrict readonly buffer Foam { float foam[]; };

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec4 out_normal_foam;  // xyz: the normal; w: the foam here (render/foam_pass.h)
// The frame's constants for water.frag, as flat varyings (see POND_WATER_FLAT_* in
// shared/water_render.h for why not the uniform block).
layout(location = POND_WATER_FLAT_EYE) flat out vec4 out_eye;
layout(location = POND_WATER_FLAT_SUN) flat out vec4 out_sun;
layout(location = POND_WATER_FLAT_SKY) flat out vec4 out_sky;
layout(location = POND_WATER_FLAT_WATER) flat out vec4 out_water;
layout(location = POND_WATER_FLAT_GROUND) flat out vec4 out_ground;
layout(location = POND_WATER_FLAT_HORIZON) flat out vec4 out_horizon;
layout(location = POND_WATER_FLAT_ABSORB) flat out vec3 out_absorb;
layout(location = POND_WATER_FLAT_POOL) flat out vec4 out_pool;
layout(location = POND_WATER_FLAT_SCREEN) flat out vec3 out_screen;
layout(location = POND_WATER_SHADOW) out vec3 out_shadow;
layout(location = POND_WATER_FLAT_SHADOW_X) flat out vec4 out_shadow_x;
layout(location = POND_WATER_FLAT_SHADOW_Y) flat out vec4 out_shadow_y;
layout(location = POND_WATER_FLAT_SHADOW_Z) flat out vec4 out_shadow_z;
layout(location = POND_WATER_FLAT_SHADOW_SUN) flat out vec4 out_shadow_sun;

void main() {
  const uint n = uint(gl_VertexIndex);  // compact: row * cols + col
  const uint cols = POND_FRAME_COLS(f), stride = POND_FRAME_STATE_STRIDE(f),
             pitch = POND_FRAME_STATE_PITCH(f);
  const uint col = n % cols, row = n / cols;
  const vec3 rest = vec3(float(col), 0.0, float(row));
  const uint m = row * pitch + col;  // the state's rows are `pitch` nodes apart
  const vec3 u = vec3(state[m], state[stride + m], state[2u * stride + m]);
  // `precise` (no contraction, no reordering): every water pipeline computes the very same position.
  // Where shadows fall the water is drawn twice, and the second draw must fail the depth test
  // exactly where the first one drew (render/frame_loop.cpp).
  precise vec3 world = (rest + u) * POND_FRAME_GRID_SPACING(f);  // grid units -> world
  precise vec4 position = f.view_proj * vec4(world, 1.0);
  out_world = world;
  out_normal_foam = vec4(normals[n].xyz, POND_FRAME_FOAM(f) > 0.0 ? foam[n] : 0.0);
  gl_Position = position;
  // w: POND_FLAT_INV_SPACING, the reciprocal: water.frag multiplies by it.
  out_eye = vec4(f.eye.xyz, 1.0 / POND_FRAME_GRID_SPACING(f));
  out_sun = vec4(f.sun.xyz, POND_FRAME_FLOOR_DEPTH(f));  // w: POND_FLAT_FLOOR_DEPTH
  out_sky = vec4(f.sky.rgb, f.caustics.x);  // the caustics' place in spare lanes (POND_FLAT_CAUSTICS)
  out_water = vec4(f.water.rgb, f.caustics.y);
  const float floor_sun = (1.0 - kFloorAmbient) * max(f.sun.y, 0.0);  // the floor's light: sky, then sun
  out_ground = vec4(f.ground.rgb * (kFloorAmbient + floor_sun), f.caustics.z);
  out_horizon = vec4(sky_horizon(f.sky.rgb), f.caustics.w);
  out_absorb = f.absorption.rgb;  // per world unit, whatever the grid's spacing
  out_pool = vec4(float(cols - 1u), float(POND_FRAME_ROWS(f) - 1u), vec2(f.caustics_size.xy));
  out_screen = f.screen.xyz;
  out_shadow = (f.shadow * vec4(world, 1.0)).xyz;
  out_shadow_x = vec4(f.shadow[0][0], f.shadow[1][0], f.shadow[2][0], f.shadow[3][0]);  // rows
  out_shadow_y = vec4(f.shadow[0][1], f.shadow[1][1], f.shadow[2][1], f.shadow[3][1]);
  out_shadow_z = vec4(f.shadow[0][2], f.shadow[1][2], f.shadow[2][2], f.shadow[3][2]);
  out_shadow_sun = vec4(f.shadow_sun.xyz, kFloorAmbient / (kFloorAmbient + floor_sun));
}
