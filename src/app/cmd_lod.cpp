// pond lod: builds the view-dependent LOD triangulation of a STATE.npy for one camera and writes
// the contract's TRIS.npy (uint32 (T, 3), node index = row * cols + col). With --repeat N it builds
// N times from the same state and reports the median warm build (the first is cold: its pages and
// caches are new), so anyone can time the builder on their own state.
#include <algorithm>
#include <chrono>
#include <limits>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "core/cpu_features.h"
#include "core/errors.h"
#include "core/npy.h"
#include "core/output_file.h"
#include "core/output_paths.h"
#include "core/text.h"
#include "lod/lod_builder.h"
#include "view/view_projection.h"

namespace pond::app {
namespace {

struct LodOptions {
  std::string state, eye, target, size, out;
  double fovy = 0, tolerance = 0;
  int repeat = 1;
};

// The median of the times after the first (the first alone when there is one).
double median_warm_ms(std::vector<double> ms) {
  if (ms.size() > 1) ms.erase(ms.begin());
  std::sort(ms.begin(), ms.end());
  const std::size_t n = ms.size();
  return n % 2 == 1 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
}

int run_lod(const LodOptions& o) {
  lod::Camera camera;
  const auto eye = parse_vec3(o.eye, "--eye"), target = parse_vec3(o.target, "--target");
  for (int k = 0; k < 3; ++k) camera.eye[k] = eye[k], camera.target[k] = target[k];
  const Size2 size = parse_size(o.size, "--size");
  camera.width = size.width, camera.height = size.height;
  camera.fovy_degrees = o.fovy;
  camera = view::checked_camera(camera, "--eye", "--target");
  lod::validate(camera, o.tolerance);
  core::validate_cpu_features_mask();  // the builder reads it; an error below is the state's
  check_output_path(o.out);
  check_outputs_spare_inputs({{"--out", o.out}}, {{"--state", o.state}});

  const NpyArray state = read_npy(o.state);
  if (state.type != NpyType::f32 || state.shape.size() != 3 || state.shape[2] != 6)
    throw InputError(quote(o.state) + " must be a float32 (rows, cols, 6) STATE.npy, got " +
                     npy_type_name(state.type) + " with " + std::to_string(state.shape.size()) +
                     " dimensions" + (state.shape.size() == 3 ? " and last dimension " +
                     std::to_string(state.shape[2]) : std::string()));
  if (state.shape[0] < 2 || state.shape[1] < 2 || state.shape[0] > 65536 || state.shape[1] > 65536)
    throw InputError(quote(o.state) + " grid must be between 2 x 2 and 65536 x 65536 nodes, got " +
                     std::to_string(state.shape[0]) + " x " + std::to_string(state.shape[1]));
  const int rows = static_cast<int>(state.shape[0]), cols = static_cast<int>(state.shape[1]);

  const lod::NodePositions positions = lod::interleaved_positions(state.as<float>().data(), rows, cols);
  lod::LodBuilder builder(rows, cols);
  std::vector<std::uint32_t> indices(builder.max_indices());
  std::size_t count = 0;
  std::vector<double> times;
  try {
    // What a running pond's solver hands the builder for free, made here from the file's nodes.
    const auto r0 = std::chrono::steady_clock::now();
    const lod::TileRanges ranges = lod::tile_ranges(positions);
    std::printf("lod: tile ranges of the state's %d x %d tiles computed in %.3f ms (not part of the build)\n",
                ranges.tiles_x(), ranges.tiles_y(),
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - r0).count());
    for (int k = 0; k < o.repeat; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      count = builder.build(positions, ranges, camera, o.tolerance, indices);
      times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
  } catch (const InputError& e) {  // the camera was checked above: this is about the positions
    throw InputError(quote(o.state) + ": " + e.what());
  }
  const double ms = median_warm_ms(times);
  char timing[96] = "";
  if (o.repeat > 1)
    std::snprintf(timing, sizeof timing, " (median of %d warm builds; the first, cold: %.3f ms)", o.repeat - 1,
                  times[0]);

  const std::size_t shape[2] = {count / 3, 3};
  write_npy(o.out, NpyType::u32, shape, std::as_bytes(std::span(indices.data(), count)));
  std::printf("lod: %zu triangles (%.2f%% of the full %zu) of a %d x %d grid at tolerance %g px, "
              "built in %.3f ms%s; wrote %s\n",
              count / 3, 100.0 * static_cast<double>(count / 3) / static_cast<double>(builder.full_triangles()),
              builder.full_triangles(), rows, cols, o.tolerance, ms, timing, escaped(o.out).c_str());
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
  sub->add_option("--fovy", o->fovy, "Vertical field of view in degrees")->required()->transform(real_number(view::kMinFovyDegrees, view::kMaxFovyDegrees, kFovyRange));
  sub->add_option("--size", o->size, "Viewport WIDTHxHEIGHT in pixels")->required();
  sub->add_option("--tolerance", o->tolerance,
                  "Screen-space error bound tau in pixels (> 0)")
      ->required()
      ->transform(real_number(std::numeric_limits<double>::min(), 1e6, "a number of pixels > 0, at most 1e6"));
  sub->add_option("--out", o->out, "Output TRIS.npy: uint32 (T, 3)")->required();
  sub->add_option("--repeat", o->repeat,
                  "Build N times from the state and report the median warm build time (default 1)")
      ->transform(whole_number(1, 100000));
  return {sub, [o] { return run_lod(*o); }};
}

}  // namespace pond::app
