#pragma once
// The windowed demo: a GLFW window with a Vulkan swapchain driven by the one frame loop
// (render/frame_loop.h), an orbit camera, splashes by mouse, the paper's modes at keys, an ImGui
// panel, and scripted input for tests.
#include <cstdint>
#include <string>

namespace pond::app::demo {

struct DemoOptions {
  std::string scene;          // "" = the embedded default scene
  std::int64_t frames = 0;    // 0 = until the window is closed
  std::string screenshot;     // the last frame as PNG
  std::string script;         // replayed input (script.h)
  int width = 1280, height = 720;
  bool vsync = true;
  bool validation = false;    // validation layer; any message makes the run fail (exit 1)
  std::string device;
  bool quiet = false;         // no summary line at the end
};

// Runs the demo; returns the exit code. Throws InputError (bad scene, script, paths) before
// opening a window, RuntimeError (no display, no Vulkan) otherwise.
int run_demo(const DemoOptions& options);

}  // namespace pond::app::demo
