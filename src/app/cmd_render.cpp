// pond render: headless rendering to PNG (offscreen image and readback; no window, no display).
#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/render_bridge.h"
#include "core/errors.h"
#include "core/output_file.h"
#include "core/output_paths.h"
#include "view/view_projection.h"

namespace pond::app {

Command add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  auto raw = std::make_shared<std::array<std::string, 3>>();  // size, eye, target as typed
  CLI::App* sub = app.add_subcommand(
      "render", "Run N steps, then render F frames offscreen and write the last as a PNG; prints ms per frame");
  sub->add_option("--scene", o->scene, "Scene JSON file (default: the embedded scene)");
  sub->add_option("--steps", o->steps, "Steps before the first frame")->required()->check(
      whole_number(0, std::int64_t{1} << 40));
  sub->add_option("--frames", o->frames, "Frames to render, each advancing view.steps_per_frame steps (default 1)")
      ->transform(whole_number(1, 1000000));
  sub->add_option("--size", (*raw)[0], "Image size WxH, e.g. 1280x720")->required();
  sub->add_option("--out", o->out, "Output PNG (the last frame)")->required();
  sub->add_option("--eye", (*raw)[1], "Camera position X,Y,Z (world; default: the scene's camera)");
  sub->add_option("--target", (*raw)[2], "Point looked at X,Y,Z");
  sub->add_option("--fovy", o->fovy, "Vertical field of view in degrees")->transform(real_number(view::kMinFovyDegrees, view::kMaxFovyDegrees, kFovyRange));
  sub->add_option("--lod-tolerance", o->lod_tolerance, "LOD screen-space error in pixels; 0 = the full mesh")
      ->transform(real_number(0.0, 1e6, "a number of pixels >= 0 (0 = the full mesh), at most 1e6"));
  sub->add_option("--solver", o->solver, "Solver: gpu (default) or a CPU backend")
      ->check(CLI::IsMember({"gpu", "scalar", "sse", "avx2", "avx512", "neon"}));
  sub->add_flag("--wireframe", o->wireframe, "Overlay the LOD triangles");
  sub->add_option("--device", o->device, "Vulkan device name (substring)");
  sub->add_flag("--validation", o->validation, "Enable the Vulkan validation layer (fails on any message)");
  sub->add_flag("--profile", o->profile,
                "Each pass's GPU time from timestamp queries; after the picture, each effect against frozen frames without it");
  return {sub, [o, raw] {
            const Size2 size = parse_size((*raw)[0], "--size");
            o->width = size.width;
            o->height = size.height;
            if (!(*raw)[1].empty()) view::check_camera_point(*(o->eye = parse_vec3((*raw)[1], "--eye")), "--eye");
            if (!(*raw)[2].empty()) view::check_camera_point(*(o->target = parse_vec3((*raw)[2], "--target")), "--target");
            if (o->eye && o->target && *o->eye == *o->target) throw InputError("--target must differ from --eye");
            check_output_path(o->out);
            check_outputs_spare_inputs({{"--out", o->out}}, {{"--scene", o->scene}});
            return run_render(*o);
          }};
}

}  // namespace pond::app
