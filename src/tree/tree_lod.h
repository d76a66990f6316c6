#pragma once
// The wind tree's level of detail, per frame and per instance: which levels are drawn as tubes and
// which as twig lines (tree_mesh.h). llvmpipe pays per triangle (vertex shading and triangle setup
// run on one thread), and at a pond's viewing distance most of a depth-8 tree's 3280 segments are
// far thinner than a pixel: as tubes they cost ~28k triangles and rasterize as scattered dots; as
// lines as opaque as the tube is wide (shaders/tree.frag) they cost a line each and cover what the
// tube would, on average. Levels are ordered in the mesh, so the choice is one level per instance.
//
// The choice is conservative: a level is a tube when its base diameter, seen from the nearest point
// of the instance's bounding sphere (bent by this frame's wind), spans kMinTubePixels or more; so
// is the leaves' shape (kMinDiamondLeafPixels).
// No Vulkan here: the tests check it from a scene's camera.
#include <array>

#include "tree/tree_mesh.h"
#include "tree/tree.h"
#include "tree/wind_state.h"

namespace pond::tree {

// Leaves shorter than this on screen (pixels) are drawn as one triangle rather than a diamond: at a
// few pixels both cover the same pixels in the same green, at half the triangles (llvmpipe's cost).
inline constexpr float kMinDiamondLeafPixels = 4.0f;

// Tubes thinner than this on screen (pixels) are drawn as twig lines. A 1-px line stands in for a
// tube up to about that width; 1.5 rather than 1 keeps a tube wherever the line would visibly thin it.
inline constexpr float kMinTubePixels = 1.5f;

// Stochastic pruning (Cook, Halstead, Planck and Ryu, "Stochastic simplification of aggregate
// detail", 2007) of what is far below a pixel: far leaves (triangles) smaller than
// kPrunedLeafArea square pixels, and twig lines narrower than kPrunedTwigPixels, are drawn as a
// uniform sample (a prefix of the mesh's shuffled order, tree_mesh.h) whose elements are enlarged
// so that the sample covers the same area on average. On llvmpipe every leaf and line costs its
// vertices and its setup on one thread whatever it covers: at the demo's distance the crown's 2187
// leaves are 1.3 px^2 each and most twigs 0.08 px wide.
inline constexpr float kPrunedLeafArea = 4.0f;     // px^2
inline constexpr float kPrunedTwigPixels = 0.25f;  // px

// Which part of n elements of `measure` (area or width, on screen) to draw where the threshold is
// `least`: all of them at their size when measure >= least; else the first `count` =
// ceil(n measure / least) (at least 1), each with its measure multiplied by `scale` = n / count, so
// that count * scale * measure = n * measure.
struct Pruning {
  std::uint32_t count = 0;
  float scale = 1.0f;
};
Pruning prune(std::uint32_t n, float measure, float least);

// The camera as the level of detail needs it.
struct TreeLodCamera {
  std::array<float, 4> depth_row{};  // view depth (clip w) of world p: dot(xyz, p) + w
  float pixels_per_unit = 0.0f;      // pixels per world unit at view depth 1
};

// From a column-major Vulkan view-projection (a perspective one: clip w is the view depth) and the
// viewport's height in pixels.
TreeLodCamera tree_lod_camera(const float* view_proj, int height);

struct Sphere {
  tree::Vec3 centre;
  float radius = 0.0f;
};

// What bounds a grown tree's drawn vertices however the wind bends it (tree units), computed once
// per tree: its rest bounding sphere, how far the article's bend can move a vertex per unit of wind
// and of twig noise, and how far the length-preserving bend can reach from the root.
struct TreeBounds {
  Sphere rest;             // every rest mesh vertex (rings and leaves included)
  tree::Vec3 root;         // rest position of the root
  float reach = 0.0f;      // longest root-to-vertex path plus the largest ring or leaf offset
  float wind_gain = 0.0f;  // max over vertices of |wX| + |wZ|
  float jitter_gain = 0.0f;  // max over vertices of |coefficients|_1
};

TreeBounds tree_bounds(const tree::Tree& tree, const TreeMesh& mesh);

// A sphere (tree units) holding every vertex of the tree's mesh bent by `frame` (pruned far leaves,
// drawn grown, may reach a little past it: it sizes the level of detail, nothing is culled by it;
// by then they are under 4 px^2, so their reach past it is a pixel or two): the article's bend
// moves a vertex by at most wind_gain * (max(|wind.x|, |wind.z|) + jitter_gain * max|q|), the
// length-preserving one keeps every vertex within `reach` of its (so moved) root.
Sphere bent_bounds(const TreeBounds& bounds, const tree::TreeWindFrame& frame);

// Pixels per tree unit at the nearest point of `bounds` (the instance's bent sphere in world units;
// `world_per_unit`: the instance's scale), or infinity when the camera is inside or beside it.
float nearest_pixels_per_unit(const TreeLodCamera& camera, const Sphere& bounds, float world_per_unit);

// The thinnest level drawn as tubes: levels >= it are tubes, the ones below it twig lines (1: all
// tubes, depth + 1: none).
int thinnest_tube_level(float pixels_per_unit, int depth);

// Whether leaves `longest_leaf` long (tree units) are drawn as diamonds rather than triangles.
bool diamond_leaves(float pixels_per_unit, float longest_leaf);

}  // namespace pond::tree
