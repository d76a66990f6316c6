// Checks a `pond lod` output against the contract with the independent mesh checker
// (mesh_checker.h), for the command-line test:
//   tris_check STATE.npy TRIS.npy EX,EY,EZ TX,TY,TZ FOVY WxH TOLERANCE
// The triangles must tile the grid (no gap, overlap, crack or T-junction; every rest normal +y),
// cover every left-out node, and keep every left-out node in view within TOLERANCE pixels. Prints
// one line (triangles, nodes left out, the largest error) and exits 0; 1 with the problem named;
// 2 when an argument or a file cannot be read. The .npy files are read here, not by pond's reader.
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/plain_npy.h"
#include "lod/mesh_checker.h"

namespace {

[[noreturn]] void bad(const std::string& what) {
  std::fprintf(stderr, "tris_check: %s\n", what.c_str());
  std::exit(2);
}

std::array<double, 3> vec3(const char* text) {
  std::array<double, 3> v{};
  if (std::sscanf(text, "%lf,%lf,%lf", &v[0], &v[1], &v[2]) != 3) bad(std::string("not X,Y,Z: ") + text);
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 8) bad("usage: tris_check STATE.npy TRIS.npy EX,EY,EZ TX,TY,TZ FOVY WxH TOLERANCE");
  const auto state = pond::test::read_plain_npy<float>(argv[1], "<f4");
  const auto tris_npy = pond::test::read_plain_npy<std::uint32_t>(argv[2], "<u4");
  if (state.shape.size() != 3 || state.shape[2] != 6) bad("STATE.npy is not (rows, cols, 6)");
  if (tris_npy.shape.size() != 2 || tris_npy.shape[1] != 3) bad("TRIS.npy is not (T, 3)");
  const int rows = static_cast<int>(state.shape[0]), cols = static_cast<int>(state.shape[1]);
  const std::vector<std::uint32_t>& tris = tris_npy.data;
  pond::lod_test::CheckCamera cam{vec3(argv[3]), vec3(argv[4]), std::atof(argv[5]), 0, 0};
  if (std::sscanf(argv[6], "%dx%d", &cam.width, &cam.height) != 2) bad(std::string("not WxH: ") + argv[6]);
  const double tolerance = std::atof(argv[7]);

  const std::string problem = pond::lod_test::topology_problem(tris, rows, cols);
  if (!problem.empty()) {
    std::printf("tris_check: the triangles do not tile the %d x %d grid: %s\n", rows, cols, problem.c_str());
    return 1;
  }
  const pond::lod_test::ErrorReport e = pond::lod_test::screen_errors(tris, rows, cols, state.data, cam);
  std::printf("tris_check: %zu triangles, %zu nodes left out (%zu in view), largest error %.4f px of %.4f\n",
              tris.size() / 3, e.left_out, e.left_out_in_view, e.max_error_px, tolerance);
  if (e.uncovered) {
    std::printf("tris_check: %zu left-out nodes are covered by no triangle\n", e.uncovered);
    return 1;
  }
  if (e.max_error_px > tolerance) {
    std::printf("tris_check: a left-out node is %.4f px from its triangle, over the tolerance %.4f\n", e.max_error_px,
                tolerance);
    return 1;
  }
  return 0;
}
