// What the wind tree costs per frame at 1280x720 on scenes/demo_257.json, by configuration (and the
// length-preserving bend against the article's, which test_tree_render.cpp used to time): frame
// loops on one device, one without the tree and one per tree configuration, drawn in turn frame by
// frame (the water frozen, so every loop does the same water work) so that a busy machine slows
// them alike. Prints each configuration's median draw ms and its excess over the loop without a
// tree: that excess is the tree's draw.
//   tree_draw_bench [FRAMES per configuration, default 200]      (set XDG_RUNTIME_DIR)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "gpu/gpu_solvers.h"
#include "render/frame_loop.h"
#include "render/render_target.h"
#include "render/tree_drawable.h"
#include "scene/scene.h"
#include "scene/session_spec.h"

namespace {

using namespace pond;

struct Config {
  const char* name;
  bool tree, level_of_detail, leaves;
  tree::TreeBend bend = tree::TreeBend::article;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::atoi(argv[1]) : 200;
  const scene::Scene scene = scene::load_scene(POND_SCENES_DIR "/demo_257.json");
  const Config configs[] = {{"no tree", false, false, false},
                            {"tubes, every level (LOD off)", true, false, true},
                            {"LOD: tubes + twig lines", true, true, true},
                            {"LOD, no leaves", true, true, false},
                            // The length-preserving bend walks every vertex's ancestors in the
                            // vertex shader: its cost against the article's bend, every level drawn.
                            {"tubes, keep-length bend", true, false, true, tree::TreeBend::keep_length}};
  gpu::Context ctx{gpu::ContextOptions{}};
  render::RenderTarget target(ctx, 1280, 720);
  gpu::GpuSolvers solvers(ctx);
  std::vector<std::unique_ptr<sim::Session>> sessions;  // before the loops that draw them
  std::vector<std::unique_ptr<render::FrameLoop>> loops;
  std::vector<std::unique_ptr<render::TreeDrawable>> trees;
  for (const Config& c : configs) {
    sessions.push_back(std::make_unique<sim::Session>(scene::session_spec(scene), sim::SolverChoice{}, solvers.factory()));
    sessions.back()->advance(200);
    sessions.back()->catch_up_wind();
    loops.push_back(std::make_unique<render::FrameLoop>(ctx, scene, *sessions.back(), &solvers, render::RenderTarget::kFormat));
    tree::TreeSpec spec = *scene.tree;
    spec.bend = c.bend;
    trees.push_back(std::make_unique<render::TreeDrawable>(ctx, *loops.back(), spec));
    trees.back()->set_level_of_detail(c.level_of_detail);
    trees.back()->set_leaves(c.leaves);
    if (c.tree) loops.back()->add_drawable(*trees.back());
  }
  render::FrameView view;
  view.camera = loops.front()->default_camera(1280, 720);
  view.wait = true;
  std::vector<std::vector<double>> ms(loops.size());
  for (int f = 0; f < frames + 5; ++f)
    for (std::size_t k = 0; k < loops.size(); ++k) {
      const double d = loops[k]->frame(target.frame_target(), view).draw_ms;
      if (f >= 5) ms[k].push_back(d);  // the first frames compile pipelines and fill caches
    }
  const double bare = median(ms.front());
  std::printf("draw ms per frame at 1280x720, %s, median of %d frames (interleaved)\n", ctx.device_name().c_str(), frames);
  for (std::size_t k = 0; k < loops.size(); ++k)
    std::printf("  %-30s %7.2f   tree %+6.2f\n", configs[k].name, median(ms[k]), median(ms[k]) - bare);
  return 0;
}
