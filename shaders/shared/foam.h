// The foam pass's CPU<->GPU layouts, declared once: included by shaders/foam.comp as GLSL and by
// src/render/foam_pass.cpp as C++.
//
// Foam is one float per node, the share of the surface it covers in [0, 1], compact (node
// row * cols + col, the normals' numbering, which water.vert reads it by). Per node it rides with
// the membrane, as the surface point it whitens does, so it drifts wherever the node is pushed.
// One update a drawn frame, over the simulated time since the last one (elapsed, time units):
//   v     = (u - u at the last update) / elapsed: the node's mean velocity since, from the
//           displacements the frame draws (a CPU solver's frame has them too, not the velocities);
//           none at the first update
//   stir  = clamp((|v| / c - kFoamStirLow) / (kFoamStirHigh - kFoamStirLow), 0, 1)
//           with c = sqrt(stiffness / mass), the membrane's own speed (grid units per time unit)
//   foam' = clamp(mix(foam, mean of its 4 neighbours, spread) * keep + gain * stir, 0, 1)
//           keep = exp(-elapsed / kFoamFade), gain = kFoamRate * elapsed,
//           spread = min(kFoamSpread * elapsed, 0.5)
// so it gathers where the water moves fast (a dragged body's wake, a ball dropping in, a splash's
// crests), spreads a little and fades over kFoamFade. It is drawn, never fed back: the physics'
// state does not see it.
#ifndef POND_FOAM_H
#define POND_FOAM_H

#ifdef __cplusplus
#include "shared/water_render.h"
namespace pond::shared::foam {
using water_render::uvec4;
using water_render::vec4;
#define POND_FOAM_CONST inline constexpr
#else
#define POND_FOAM_CONST const
#endif

#define POND_FOAM_LOCAL_X 64  // foam.comp's workgroup: nodes along a row (one workgroup row a node row)

// Its binding in the water's set (shared/water_render.h: the passes' follow the set's own), a
// storage buffer read by water.vert, and its lane of the water's frame uniforms: 1 where the water
// draws foam, 0 where not (the binding then holds any buffer of a float per node or more).
#define POND_FOAM_WATER_BINDING 7
#define POND_FRAME_FOAM(frame) ((frame).sun.w)

// The foam pass's own bindings (set 0), storage buffers.
#define POND_FOAM_BINDING_STATE 0  // the water's displacements (water_gpu.h's layout: stride, pitch; ux uy uz)
#define POND_FOAM_BINDING_FROM 1   // the foam of the last update
#define POND_FOAM_BINDING_TO 2     // this update's
#define POND_FOAM_BINDING_LAST 3   // vec4 per node, compact: the displacement at the last update (xyz)
#define POND_FOAM_BINDINGS 4

struct FoamPush {
  uvec4 grid;   // rows, cols, the state's stride (floats) and pitch (nodes)
  vec4 update;  // x: keep; y: gain; z: spread; w: 1 / (c * elapsed), 0 at the first update
};

// Speeds relative to c: below kFoamStirLow no foam gathers, from kFoamStirHigh it gathers at kFoamRate.
POND_FOAM_CONST float kFoamStirLow = 0.2f;
POND_FOAM_CONST float kFoamStirHigh = 0.5f;
POND_FOAM_CONST float kFoamRate = 0.5f;    // coverage per time unit at full stir
POND_FOAM_CONST float kFoamFade = 40.0f;   // time units for foam to fall to 1/e
POND_FOAM_CONST float kFoamSpread = 0.02f; // per time unit

#ifdef __cplusplus
}  // namespace pond::shared::foam
#endif
#endif  // POND_FOAM_H
