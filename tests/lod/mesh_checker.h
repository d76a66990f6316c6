#pragma once
// Independent checks of a LOD triangulation, written from the contract (TRIS.npy and the LOD
// screen-space error in ARCHITECTURE.md) without any of the builder's code: plain edge maps,
// signed areas, and a brute-force rasterization in index space.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace pond::lod_test {

// "" when the triangles tile the rows x cols grid: indices in range, every triangle's rest normal
// (from (col, 0, row)) points to +y, every interior edge is used exactly once in each direction,
// edges used once lie on the grid border, and the parametric areas add up to (rows-1)(cols-1).
std::string topology_problem(const std::vector<std::uint32_t>& tris, int rows, int cols);

struct CheckCamera {
  std::array<double, 3> eye, target;
  double fovy_degrees;
  int width, height;
};

struct ErrorReport {
  double max_error_px = 0;     // over left-out nodes inside the frustum
  std::size_t left_out = 0;    // nodes not used as vertices
  std::size_t left_out_in_view = 0;
  std::size_t uncovered = 0;   // left-out nodes no triangle covers (index space)
};

// Every left-out node's screen error against the triangle covering it (barycentric in index
// space; for a node on an edge, the worst of its triangles). `state` is rows * cols * 6 floats.
ErrorReport screen_errors(const std::vector<std::uint32_t>& tris, int rows, int cols,
                          const std::vector<float>& state, const CheckCamera& camera);

}  // namespace pond::lod_test
