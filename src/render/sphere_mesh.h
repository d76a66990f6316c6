#pragma once
// The unit sphere the bodies are drawn with: an icosahedron whose triangles are split in four
// `subdivisions` times, every new point pushed out to the sphere. Built once; each body is an
// instance of it (render/body_drawable.h). Its points are their own normals, and its triangles wind
// counter-clockwise seen from outside (back faces can be culled).
#include <array>
#include <cstdint>
#include <vector>

namespace pond::render {

struct SphereMesh {
  std::vector<std::array<float, 4>> points;  // xyz on the unit sphere, w = 1
  std::vector<std::uint32_t> indices;        // triangle list
};

// 12 points and 20 triangles at 0 subdivisions; each one multiplies the triangles by 4.
SphereMesh build_sphere_mesh(int subdivisions);

// The longest edge of `mesh` (unit-sphere units): its coarsest place.
double longest_edge(const SphereMesh& mesh);

// How far, in pixels, the outline of a sphere `radius_px` pixels in radius drawn with edges of
// (unit-sphere) length `edge` falls inside the true one: the chord's sagitta, R (1 - sqrt(1 - e^2/4)).
double outline_error_px(double radius_px, double edge);

}  // namespace pond::render
