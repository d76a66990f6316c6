// pond check: the CPU-GPU parity suite as a user command (check_bridge.h).
#include "app/check_bridge.h"
#include "app/cli_parse.h"
#include "app/commands.h"

namespace pond::app {

Command add_check_command(CLI::App& app) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* sub = app.add_subcommand(
      "check", "Run built-in scenes on the GPU and the CPU and say whether this device gives the CPU's bits");
  sub->add_option("--device", o->device, "Vulkan device name (substring); default: the most capable device");
  sub->add_option("--steps", o->steps, "Steps of every case (default: each case's own, 2000-3000)")
      ->transform(whole_number(1, 10000000));
  return {sub, [o] { return run_check(*o); }};
}

}  // namespace pond::app
