// pond lod: builds the view-dependent LOD triangulation of a STATE.npy for one camera and writes
// the contract's TRIS.npy (uint32 (T, 3), node index = row * cols + col).
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "core/errors.h"
#include "core/npy.h"
#include "core/output_file.h"
#include "lod/lod_builder.h"

namespace pond::app {
namespace {

struct LodOptions {
  std::string state, eye, target, size, out;
  double fovy = 0, tolerance = 0;
};

int run_lod(const LodOptions& o) {
  lod::Camera camera;
  const auto eye = parse_vec3(o.eye, "--eye"), target = parse_vec3(o.target, "--target");
  for (int k = 0; k < 3; ++k) camera.eye[k] = eye[k], camera.target[k] = target[k];
  const Size2 size = parse_size(o.size, "--size");
  camera.width = size.width, camera.height = size.height;
  camera.fovy_degrees = o.fovy;
  lod::validate(camera, o.tolerance);
  check_output_path(o.out);

  const NpyArray state = read_npy(o.state);
  if (state.type != NpyType::f32 || state.shape.size() != 3 || state.shape[2] != 6)
    throw InputError(o.state + " must be a float32 (rows, cols, 6) STATE.npy, got " +
                     npy_type_name(state.type) + " with " + std::to_string(state.shape.size()) +
                     " dimensions" + (state.shape.size() == 3 ? " and last dimension " +
                     std::to_string(state.shape[2]) : std::string()));
  if (state.shape[0] < 2 || state.shape[1] < 2 || state.shape[0] > 65536 || state.shape[1] > 65536)
    throw InputError(o.state + " grid must be between 2 x 2 and 65536 x 65536 nodes, got " +
                     std::to_string(state.shape[0]) + " x " + std::to_string(state.shape[1]));
  const int rows = static_cast<int>(state.shape[0]), cols = static_cast<int>(state.shape[1]);

  lod::LodBuilder builder(rows, cols);
  std::vector<std::uint32_t> indices(builder.max_indices());
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t count = 0;
  try {
    count = builder.build(lod::interleaved_positions(state.as<float>().data(), rows, cols), camera,
                          o.tolerance, indices);
  } catch (const InputError& e) {  // the camera was checked above: this is about the positions
    throw InputError(o.state + ": " + e.what());
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  const std::size_t shape[2] = {count / 3, 3};
  write_npy(o.out, NpyType::u32, shape, std::as_bytes(std::span(indices.data(), count)));
  std::printf("lod: %zu triangles (%.2f%% of the full %zu) of a %d x %d grid at tolerance %g px, "
              "built in %.3f ms; wrote %s\n",
              count / 3, 100.0 * static_cast<double>(count / 3) / static_cast<double>(builder.full_triangles()),
              builder.full_triangles(), rows, cols, o.tolerance, ms, o.out.c_str());
  return 0;
}

}  // namespace

Command add_lod_command(CLI::App& app) {
  auto o = std::make_shared<LodOptions>();
  CLI::App* sub = app.add_subcommand(
      "lod", "Build the view-dependent LOD triangulation of a STATE.npy and write TRIS.npy");
  sub->add_option("--state", o->state, "Input STATE.npy: float32 (rows, cols, 6)")->required();
  sub->add_option("--eye", o->eye, "Camera position X,Y,Z (world units)")->required();
  sub->add_option("--target", o->target, "Point the camera looks at X,Y,Z")->required();
  sub->add_option("--fovy", o->fovy, "Vertical field of view in degrees, in (0, 180)")->required();
  sub->add_option("--size", o->size, "Viewport WIDTHxHEIGHT in pixels")->required();
  sub->add_option("--tolerance", o->tolerance,
                  "Screen-space error bound tau in pixels (> 0)")->required();
  sub->add_option("--out", o->out, "Output TRIS.npy: uint32 (T, 3)")->required();
  return {sub, [o] { return run_lod(*o); }};
}

}  // namespace pond::app
