// The demo in builds without Vulkan and GLFW (the IA-32 build): says so (exit 1).
#include <cstdio>

#include "app/demo/demo_app.h"

namespace pond::app::demo {

int run_demo(const DemoOptions&) {
  std::fprintf(stderr,
               "pond: the windowed demo is not in this build (built without Vulkan); the headless commands "
               "are: pond simulate --steps 200 --out state.npy\n");
  return 1;
}

}  // namespace pond::app::demo
