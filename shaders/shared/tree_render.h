// The wind tree renderer's CPU<->GPU layouts, declared once: included by shaders/tree.vert,
// tree.frag, tree_pose.comp (the parity test) as GLSL and by src/tree/tree_mesh.cpp and
// src/render/tree_*.cpp as C++, where the static_asserts below pin sizes and offsets.
//
// One descriptor set (set 0):
//   POND_TREE_BINDING_FRAME     uniform TreeRenderFrame (std140), per frame slot
//   POND_TREE_BINDING_SKELETON  storage buffer: the tree's vertices, kTreeVertexFloats floats each
//                               (TreeVertex of tree_wind.h: position, wX, wZ, jitter coefficients)
//   POND_TREE_BINDING_PARENTS   storage buffer: int per tree vertex, the parent (-1 for the root)
// The two storage buffers are what the length-preserving bend walks (shared/tree_pose.h).
// Push constants: TreeInstance, one draw of a tree instance (its foot, its scale, its own wind
// frame, and the level of detail's pruning of the part drawn).
//
// The mesh is a vertex buffer of TreeMeshVertex. Every mesh vertex carries the article's per-vertex
// data (position, wX, wZ, jitter: the original's normal/binormal/tangent attributes) of the branch
// vertex it belongs to, plus a rest offset from it: a tube's ring around a skeleton vertex and a
// leaf's corners move exactly as that vertex moves. Lines are mesh vertices with a zero offset.
#ifndef POND_TREE_RENDER_H
#define POND_TREE_RENDER_H

#include "tree_wind.h"

#define POND_TREE_BINDING_FRAME 0
#define POND_TREE_BINDING_SKELETON 1
#define POND_TREE_BINDING_PARENTS 2
#define POND_TREE_POSE_LOCAL_X 64

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#define POND_CONST inline constexpr
namespace pond::shared::tree_wind {
struct uvec4 {
  uint x = 0, y = 0, z = 0, w = 0;
};
struct mat4 {
  float m[16] = {};  // column-major, as GLSL
};
#else
#define POND_CONST const
#endif

// Vertex attribute locations after the article's four (tree_wind.h: 0..3).
POND_CONST int kTreeAttribOffset = 4;
POND_CONST int kTreeAttribNormal = 5;
POND_CONST int kTreeAttribInfo = 6;

// TreeMeshVertex.info.y: what a vertex belongs to (the fragment shader's material).
POND_CONST uint kTreeMaterialLine = 0u;  // the article's look: unlit lines
POND_CONST uint kTreeMaterialBark = 1u;  // tube surface
POND_CONST uint kTreeMaterialLeaf = 2u;  // leaf, lit from both sides
POND_CONST uint kTreeMaterialTwig = 3u;  // a twig thinner than a pixel or so drawn as a line: bark,
                                         // lit as its tube on average, lighting the pixels it would

// tree.vert -> tree.frag: the frame's constants as flat varyings, not read from the uniform block
// in the fragment shader (llvmpipe gathers those per lane: see POND_WATER_FLAT_* in water_render.h).
POND_CONST int kTreeFlatEye = 5;     // TreeRenderFrame::eye.xyz
POND_CONST int kTreeFlatSun = 6;     // TreeRenderFrame::sun.xyz
POND_CONST int kTreeFlatSky = 7;     // TreeRenderFrame::sky.rgb
POND_CONST int kTreeFlatAlbedo = 8;  // the vertex's material colour: line, bark (bark, twig) or leaf

// The longest root-to-vertex chain the length-preserving walk follows: the root plus one vertex
// per level, and a tree has at most 10 levels (tree::kMaxTreeDepth).
POND_CONST int kTreeMaxChain = 11;

// Per frame slot (std140): the camera and the light, shared by every instance.
struct TreeRenderFrame {
  mat4 view_proj;  // world -> clip, Vulkan conventions (the water's matrix)
  vec4 eye;        // xyz: camera position (world)
  vec4 sun;        // xyz: unit direction toward the sun
  vec4 sky;        // rgb: sky colour at the zenith (linear), the ambient light
  vec4 bark;       // rgb: bark colour (linear)
  vec4 leaf;       // rgb: leaf colour (linear)
  vec4 line;       // rgb: the line look's colour (linear); a: unused
  vec4 lod;        // twig lines: x: pixels per world unit at unit view depth (clip w); yz: viewport
                   // size (pixels)
  mat4 light_proj; // world -> clip of the sun's shadow map (tree_shadow.vert; render/shadow_pass.h),
                   // written by the shadow pass's draw
};

// Push constants (std430): one instance. Its bent tree, in tree units (trunk length 1), is placed
// at base.xyz + bent * base.w.
struct TreeInstance {
  vec4 base;           // xyz: the trunk's foot (world); w: world units per tree unit
  TreeWindFrame wind;  // this instance's wind, q, time (with its phase) and bend mode
  vec4 pruning;        // the level of detail's pruning of this draw (tree/tree_lod.h): x: leaves'
                       // size scale (about their centres); y: twig lines' width scale; z: the
                       // mesh's longest leaf (tree units: unpacks the centres); w: the mirrored
                       // draw's target pixels per frame pixel (tree_mirror.vert), else 0
};

#ifdef __cplusplus
// One mesh vertex (96 bytes).
struct TreeMeshVertex {
  TreeVertex branch;  // the branch vertex's article data: position, wX, wZ, jitter (tree units)
  vec4 offset;        // xyz: rest offset from the branch vertex (tree units); w: 0, or for twig
                      // lines the tube's mean width at this vertex (tree units)
  vec4 normal;        // xyz: rest normal (unit; zero for lines, the segment's direction for twig
                      // lines); w: 0
  uvec4 info;         // x: branch vertex index; y: material; z: shade variation 0..255; w: leaves:
                      // the leaf's centre offset / the longest leaf, packSnorm4x8 (x, y, z, 0); else 0
};
static_assert(sizeof(uvec4) == 16 && sizeof(mat4) == 64);
static_assert(sizeof(TreeMeshVertex) == 96);
static_assert(offsetof(TreeMeshVertex, branch) == 0 && offsetof(TreeMeshVertex, offset) == 48 &&
              offsetof(TreeMeshVertex, normal) == 64 && offsetof(TreeMeshVertex, info) == 80);
static_assert(sizeof(TreeRenderFrame) == 240);
static_assert(offsetof(TreeRenderFrame, eye) == 64 && offsetof(TreeRenderFrame, sun) == 80 &&
              offsetof(TreeRenderFrame, sky) == 96 && offsetof(TreeRenderFrame, bark) == 112 &&
              offsetof(TreeRenderFrame, leaf) == 128 && offsetof(TreeRenderFrame, line) == 144 &&
              offsetof(TreeRenderFrame, lod) == 160 && offsetof(TreeRenderFrame, light_proj) == 176);
static_assert(sizeof(TreeInstance) == 80 && offsetof(TreeInstance, wind) == 16 && offsetof(TreeInstance, pruning) == 64);
}  // namespace pond::shared::tree_wind
#endif
#undef POND_CONST
#endif
