// pond [demo]: the windowed demo. Not built yet (its issue is open): says so and how to run headless.
#include <cstdio>

#include "app/commands.h"

namespace pond::app {

Command add_demo_command(CLI::App&) {
  return {nullptr, [] {
            std::fprintf(stderr,
                         "pond: the windowed demo is not in this version yet; run the simulation "
                         "headless instead: pond simulate --steps 200 --out state.npy\n");
            return 1;
          }};
}

}  // namespace pond::app
