// pond: parses the command line and dispatches to one subcommand. Errors are exceptions caught here
// once: bad input (InputError, CLI11 parse errors) exits 2, run-time failures exit 1, each with one
// line on stderr.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "app/commands.h"
#include "core/errors.h"

int main(int argc, char** argv) {
  CLI::App app{"pond: a spring-mass water surface and a tree in the wind, on Vulkan compute", "pond"};
  app.require_subcommand(0, 1);
  try {
    using namespace pond::app;
    const std::vector<Command> commands = {add_demo_command(app), add_simulate_command(app),
                                           add_render_command(app), add_lod_command(app),
                                           add_tree_command(app)};
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == 0) return app.exit(e);  // --help
      std::fprintf(stderr, "pond: %s\n", e.what());
      return 2;
    }
    for (const Command& c : commands)
      if (c.sub && c.sub->parsed()) return c.run();
    return commands.front().run();  // no subcommand: the demo
  } catch (const pond::InputError& e) {
    std::fprintf(stderr, "pond: %s\n", e.what());
    return 2;
  } catch (const pond::RuntimeError& e) {
    std::fprintf(stderr, "pond: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "pond: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pond: %s\n", e.what());
    return 1;
  }
}
