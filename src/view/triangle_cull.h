#pragma once
// Which of a mesh's triangles each of a frame's draws needs, sorted on the CPU from the triangles'
// corners in clip space: those wholly outside one plane of the view volume are left out, those
// wholly inside come first and those across its boundary last, in a draw of their own; and a
// scissored draw (a shadow rectangle, frame_loop.cpp) gets only the triangles whose pixels can fall
// in its rectangle.
//
// Why: a software rasterizer sends every primitive of a batch that needs clipping through its
// general (slow) path, and runs the vertex and setup work of a scissored draw for every triangle
// before the scissor rejects them. On a GPU both are free, and the lists cost a draw and a few
// microseconds of CPU. Both lists of a draw cover exactly the triangles it showed before, so the
// picture is the same (a triangle's pixels do not depend on the draw it is in).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "view/pixel_rect.h"

namespace pond::view {

// World positions by vertex index, structure of arrays.
struct MeshPositions {
  std::span<const float> x, y, z;
};

// One draw's part of CulledMesh::indices: `inside` indices from `first`, then `across` more.
struct IndexRange {
  std::uint32_t first = 0, inside = 0, across = 0;
};

struct CulledMesh {
  std::vector<std::uint32_t> indices;  // the ranges' lists, one after another
  IndexRange whole;                    // the view's
  std::vector<IndexRange> rects;       // each rectangle's, in the given order

  // cull_triangles()'s scratch: the kept triangles (their first index) and, for those wholly
  // inside, their pixels' bounding box.
  struct Kept {
    std::uint32_t first = 0;
    bool inside = false;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  };
  std::vector<Kept> kept;
};

// Sorts `triangles` (3 vertex indices each, counter-clockwise or not) for a width x height view
// (`view_proj`: column-major, Vulkan clip space: depth 0..w) and `rects` of its pixels into `out`
// (its vectors reused). Conservative: a triangle is left out only when all three corners are
// outside one plane by a margin, and a rectangle keeps every triangle across the view's boundary
// and every other one whose pixel bounding box, grown by a pixel, meets it.
void cull_triangles(std::span<const std::uint32_t> triangles, const MeshPositions& positions,
                    const std::array<float, 16>& view_proj, int width, int height, std::span<const PixelRect> rects,
                    CulledMesh& out);

}  // namespace pond::view
