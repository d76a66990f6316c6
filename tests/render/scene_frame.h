#pragma once
// One frame of a scene file's text as `pond render` draws it, for the effect tests (caustics,
// reflections, shadows): the scene's trees (if it has any) and its bodies drawn, the picture's
// effects as given, `steps` steps first, read back.
#include <cstdint>
#include <optional>
#include <string>

#include "drawn_session.h"
#include "image_compare.h"
#include "render/body_drawable.h"
#include "render/render_target.h"
#include "render/tree_drawable.h"
#include "scene/scene.h"

namespace pond::test {

inline Rgba render_scene_frame(const gpu::Context& ctx, const std::string& json, const view::Effects& effects, int width,
                               int height, std::int64_t steps = 0) {
  const scene::Scene scene = scene::parse_scene(json, "test");
  DrawnSession drawn(ctx, scene, {}, render::RenderTarget::kFormat);
  render::FrameLoop& loop = drawn.loop;
  std::optional<render::TreeDrawable> tree;
  if (scene.tree) loop.add_drawable(tree.emplace(ctx, loop, *scene.tree));
  render::BodyDrawable bodies(ctx, loop);
  loop.add_drawable(bodies);
  render::RenderTarget target(ctx, width, height);
  drawn.session.advance(steps);
  drawn.session.catch_up_wind();
  render::FrameView view;
  view.camera = loop.default_camera(width, height);
  view.wait = true;
  view.effects = effects;
  loop.frame(target.frame_target(), view);
  return Rgba{width, height, target.read_rgba()};
}

}  // namespace pond::test
