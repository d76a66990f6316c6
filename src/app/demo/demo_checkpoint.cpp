// The demo's checkpoints (demo_app_impl.h; docs/checkpoints.md): F5 / the panel's "save" / a
// script's `save FILE` write the pond as it is, with its edits, the camera and the view; F9 /
// "load" / `load FILE` take one back: the water, the bodies and the wind go on from it, on the
// solver the demo uses now.
#include "app/demo/demo_app_impl.h"
#include "scene/checkpoint.h"

namespace pond::app::demo {

void DemoApp::save_checkpoint(const std::string& path) {
  scene::Scene scene = base_scene_;
  scene.view.steps_per_frame = settings_.steps_per_frame;
  scene.view.lod_tolerance_px = settings_.lod_tolerance_px;
  scene.view.effects = settings_.effects;
  const lod::Camera c = current_camera();
  scene.camera = view::CameraSpec{.eye = c.eye, .target = c.target, .fovy_degrees = c.fovy_degrees};
  if (tree_) scene.tree = tree_->spec();
  try {
    scene::write_checkpoint(path, scene, *session_, session_->image());
    notice("saved " + path + " at step " + std::to_string(session_->steps_done()));
  } catch (const Error& e) {  // a folder that is not there, a full disk: said, the demo goes on
    notice(std::string("not saved: ") + e.what());
  }
}

void DemoApp::load_checkpoint(const std::string& path) {
  scene::Checkpoint checkpoint;
  try {
    checkpoint = scene::read_checkpoint(path);
  } catch (const InputError& e) {
    notice(std::string("not loaded: ") + e.what());
    return;
  }
  base_scene_ = checkpoint.scene;
  adopt_scene_settings();
  grab_ = BodyGrab{};
  if (loop_) loop_->wait_idle();
  bodies_.reset();
  tree_.reset();
  loop_.reset();
  make_session(base_scene_, &checkpoint.image);
  build_loop();
  if (const std::optional<view::CameraSpec>& c = base_scene_.camera) {  // the saved view becomes home
    camera_.set_home(lod::Camera{.eye = c->eye, .target = c->target, .fovy_degrees = c->fovy_degrees});
    camera_.reset();
  }
  notice("loaded " + path + " at step " + std::to_string(session_->steps_done()));
}

}  // namespace pond::app::demo
