// pond [demo]: the windowed demo (app/demo/). Its options are registered on the app itself and on
// the `demo` subcommand, bound to the same variables, so `pond --frames 10` and
// `pond demo --frames 10` are the same run. Builds without Vulkan link cmd_demo_none.cpp, which
// says the demo is not in that build.
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/demo/demo_app.h"
#include "core/errors.h"

namespace pond::app {
namespace {

struct DemoCli {
  demo::DemoOptions options;
  std::string size = "1280x720";
  bool no_vsync = false;
  std::vector<CLI::Option*> screenshot;  // on the app and on `demo`: given at all, even as ""
};

void add_demo_options(CLI::App& app, DemoCli& cli) {
  app.add_option("--scene", cli.options.scene, "Scene JSON file (default: the embedded scene)")->type_name("FILE");
  app.add_option("--frames", cli.options.frames, "Run N frames, then exit 0 (default: until closed)")
      ->type_name("N")
      ->transform(whole_number(1, 1000000000));
  cli.screenshot.push_back(
      app.add_option("--screenshot", cli.options.screenshot, "Save the last frame (of --frames N) as PNG")->type_name("FILE"));
  app.add_option("--script", cli.options.script,
                 "Replay input events from a text file (lines like 'frame 10 click 640 360', see README)")
      ->type_name("FILE");
  // For tests and measurements, not in --help.
  app.add_option("--size", cli.size, "Window size WxH")->group("");
  app.add_flag("--no-vsync", cli.no_vsync, "Present without waiting for vertical blank")->group("");
  app.add_flag("--validation", cli.options.validation,
               "Enable the Vulkan validation layer; any message fails the run (also POND_VALIDATION=1)")
      ->group("");
  app.add_option("--device", cli.options.device, "Vulkan device name substring")->group("");
  app.add_flag("--quiet", cli.options.quiet, "No summary line at exit")->group("");
}

}  // namespace

Command add_demo_command(CLI::App& app) {
  auto cli = std::make_shared<DemoCli>();
  CLI::App* sub = app.add_subcommand("demo", "The windowed demo (also the default when no command is named)");
  add_demo_options(app, *cli);
  add_demo_options(*sub, *cli);
  return {sub, [cli] {
            demo::DemoOptions o = cli->options;
            for (const CLI::Option* shot : cli->screenshot)
              if (shot->count() > 0 && o.screenshot.empty()) throw InputError("--screenshot must name a file");
            const Size2 size = parse_size(cli->size, "--size");
            o.width = size.width, o.height = size.height;
            o.vsync = !cli->no_vsync;
            if (const char* v = std::getenv("POND_VALIDATION"); v && std::string(v) == "1") o.validation = true;
            return demo::run_demo(o);
          }};
}

}  // namespace pond::app
