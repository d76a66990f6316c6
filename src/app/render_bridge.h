#pragma once
// The one door from `pond render`'s option parsing (built everywhere) to the Vulkan renderer
// (render_bridge_vulkan.cpp); IA-32 builds link render_bridge_none.cpp, which says the renderer is
// not in this build.
#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace pond::app {

struct RenderOptions {
  std::string scene, out, solver = "gpu", device;
  std::int64_t steps = -1;
  int frames = 1;
  int width = 0, height = 0;
  std::optional<std::array<double, 3>> eye, target;
  std::optional<double> fovy, lod_tolerance;
  bool wireframe = false;
  bool validation = false;
  bool profile = false;  // each pass's GPU time (timestamps); after the picture, each effect's cost by frozen frames
};

int run_render(const RenderOptions& options);

}  // namespace pond::app
