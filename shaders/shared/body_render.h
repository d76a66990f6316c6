// The bodies' renderer (lit spheres), its CPU<->GPU layouts declared once: included by
// shaders/body.vert and body.frag as GLSL and by src/render/body_*.cpp as C++, where the
// static_asserts below pin sizes and offsets.
//
// No descriptor set: the frame's camera and light are push constants (BodyFrame), the sphere mesh
// is a vertex buffer of unit-sphere points (vec4: xyz, w = 1; the point is its own normal), and
// every body is one instance of it: its size and colour (BodyInstance, an instance-rate vertex
// buffer written per frame slot from the bodies' specs) and its centre, read straight from the
// bodies' states where the solver keeps them (shared/bodies.h BodyState, grid units: the GPU
// solver's own buffer, as another instance-rate vertex buffer).
#ifndef POND_BODY_RENDER_H
#define POND_BODY_RENDER_H

#include "shared/water_render.h"

#ifdef __cplusplus
#include <cstddef>
namespace pond::shared::body_render {
using water_render::mat4;
using water_render::vec4;
#define POND_BODY_RENDER_CONST inline constexpr
#else
#define POND_BODY_RENDER_CONST const
#endif

// Vertex attribute locations: the mesh (binding 0, per vertex), the instance (binding 1) and the
// body's state (binding 2, per instance).
POND_BODY_RENDER_CONST int kBodyAttribPoint = 0;   // vec4: a unit-sphere point (= its normal)
POND_BODY_RENDER_CONST int kBodyAttribSize = 1;    // vec4: x radius (world), y grid spacing (the state's unit)
POND_BODY_RENDER_CONST int kBodyAttribAlbedo = 2;  // vec4: rgb its colour (linear); a: 1 while held
POND_BODY_RENDER_CONST int kBodyAttribCentre = 3;  // vec3: the centre in grid units (BodyState x, y, z)

// body.vert -> body.frag: the frame's constants as flat varyings (as the water's: llvmpipe gathers
// push constants per lane in a fragment shader, see POND_WATER_FLAT_* in water_render.h).
POND_BODY_RENDER_CONST int kBodyFlatEye = 2;
POND_BODY_RENDER_CONST int kBodyFlatSun = 3;
POND_BODY_RENDER_CONST int kBodyFlatSky = 4;
POND_BODY_RENDER_CONST int kBodyFlatAlbedo = 5;

// Push constants (std430, vertex stage): the camera and the light of the frame.
struct BodyFrame {
  mat4 view_proj;  // world -> clip, Vulkan conventions (the water's matrix)
  vec4 eye;        // xyz: camera position (world)
  vec4 sun;        // xyz: unit direction toward the sun
  vec4 sky;        // rgb: sky colour at the zenith (linear), the ambient light
};

// One body as drawn: an instance of the unit sphere (its centre comes from its state).
struct BodyInstance {
  vec4 size;    // x: radius (world units); y: the grid spacing (world units per grid unit); zw: 0
  vec4 albedo;  // rgb: colour (linear); a: 1 while the demo holds the body, else 0
};

#ifdef __cplusplus
static_assert(sizeof(BodyFrame) == 112 && offsetof(BodyFrame, eye) == 64 && offsetof(BodyFrame, sun) == 80 &&
              offsetof(BodyFrame, sky) == 96);
static_assert(sizeof(BodyInstance) == 32 && offsetof(BodyInstance, albedo) == 16);
}  // namespace pond::shared::body_render
#endif
#undef POND_BODY_RENDER_CONST
#endif
