// What input does to the demo (demo_app_impl.h): keys and the panel's requests, splashes, the
// wind's controls, the bodies grabbed, dropped, added and removed. Edits go to the session; a
// splash is a dispatch the next frame's compute applies.
#include <cmath>
#include <cstdio>

#include "app/demo/demo_app_impl.h"
#include "app/demo/picking.h"
#include "app/demo/scene_modes.h"
#include "core/errors.h"
#include "sim/backends.h"

namespace pond::app::demo {

std::array<double, 3> DemoApp::middle_of_pond() const {
  const sim::WaterModel& m = session_->model();
  return {0.5 * (m.cols - 1) * m.spacing, 3.0 * m.spacing, 0.5 * (m.rows - 1) * m.spacing};
}

void DemoApp::on_toggle_effect(const view::EffectEntry& effect) {
  settings_.effects.*effect.flag = !(settings_.effects.*effect.flag);
}

void DemoApp::on_action(Action action) {
  switch (action) {
    case Action::quit: quit_ = true; break;
    case Action::help: settings_.show_help = !settings_.show_help; break;
    case Action::panel: settings_.show_panel = !settings_.show_panel; break;
    case Action::pause: settings_.paused = !settings_.paused; break;
    case Action::step: settings_.paused = true, settings_.step_once = true; break;
    case Action::reset_water: apply_requests({.reset_water = true}); break;
    case Action::reset_camera: camera_.reset(); break;
    case Action::border:
      settings_.modes.border = next_border(settings_.modes.border);
      apply_requests({.rebuild_scene = true});
      break;
    case Action::all_vertical:
      settings_.modes.all_vertical = !settings_.modes.all_vertical;
      apply_requests({.rebuild_scene = true});
      break;
    case Action::islands:
      settings_.modes.islands = !settings_.modes.islands;
      apply_requests({.rebuild_scene = true});
      break;
    case Action::wireframe: settings_.wireframe = !settings_.wireframe; break;
    case Action::toggle_effect: break;  // needs the effect: on_toggle_effect
    case Action::tau_up: settings_.lod_tolerance_px = next_tolerance(settings_.lod_tolerance_px, true); break;
    case Action::tau_down: settings_.lod_tolerance_px = next_tolerance(settings_.lod_tolerance_px, false); break;
    case Action::steps_up: settings_.steps_per_frame = std::min<std::int64_t>(64, settings_.steps_per_frame + 1); break;
    case Action::steps_down: settings_.steps_per_frame = std::max<std::int64_t>(0, settings_.steps_per_frame - 1); break;
    case Action::solver:
      settings_.gpu_solver = !settings_.gpu_solver;
      apply_requests({.switch_solver = true});
      break;
    case Action::rain: settings_.rain.on = !settings_.rain.on; break;
    case Action::vsync: settings_.vsync = !settings_.vsync; break;
    case Action::save_checkpoint: save_checkpoint(settings_.checkpoint_file); break;
    case Action::load_checkpoint: load_checkpoint(settings_.checkpoint_file); break;
    case Action::drop_ball: break;  // needs the cursor: InputDispatch calls on_drop_ball
    case Action::screenshot: {
      char name[32];
      std::snprintf(name, sizeof name, "pond-%04d.png", shot_counter_++);
      take_screenshot_next(name);
      break;
    }
  }
}

// The wind blows along the drag as seen on screen: right on screen is the camera's right, up on
// screen is away from the camera (both in the ground plane).
void DemoApp::on_wind_drag(double x0, double y0, double x, double y) {
  if (!tree_ || (x == x0 && y == y0)) return;
  const lod::Camera c = camera_.camera(1, 1);
  const double fx = c.target[0] - c.eye[0], fz = c.target[2] - c.eye[2];
  const double right_x = -fz, right_z = fx;  // forward rotated a quarter turn clockwise seen from +y
  const double wx = (x - x0) * right_x - (y - y0) * fx, wz = (x - x0) * right_z - (y - y0) * fz;
  session_->set_wind_direction(std::atan2(wz, wx));
}

void DemoApp::on_splash(double x, double y, SplashKind kind) {
  const sim::WaterModel& model = session_->model();
  const std::optional<SurfaceHit> hit =
      intersect_surface(pixel_ray(current_camera(), x, y), model, session_->reader().all_displacements());
  if (!hit) {
    settings_.message = "the click missed the water";
    return;
  }
  const double h = model.spacing;
  sim::Perturbation p{.row = hit->row, .col = hit->col, .radius = settings_.splash.radius * h};
  switch (kind) {
    case SplashKind::velocity:
      p.amplitude = settings_.splash.velocity * h;
      p.target = sim::PerturbTarget::velocity;
      break;
    case SplashKind::position:
      p.amplitude = settings_.splash.position * h;
      p.target = sim::PerturbTarget::position;
      break;
    case SplashKind::explosion:
      p.amplitude = settings_.splash.explosion * h;
      p.radius = settings_.splash.explosion_radius * h;
      p.target = sim::PerturbTarget::velocity;
      break;
  }
  session_->splash(p);
  char text[96];
  std::snprintf(text, sizeof text, "splash at row %.1f col %.1f", hit->row, hit->col);
  settings_.message = text;
}

void DemoApp::notice(const std::string& text) {
  settings_.message = text;
  if (!options_.quiet) std::printf("pond demo: frame %lld: %s\n", static_cast<long long>(frame_), text.c_str());
}

bool DemoApp::on_grab(double x, double y) {
  const std::optional<std::size_t> b = grab_.grab(*session_, pixel_ray(current_camera(), x, y));
  if (!b) return false;
  grab_.move_cursor(x, y);
  notice("holding body " + std::to_string(*b));
  return true;
}

void DemoApp::on_grab_release(double x, double y) {
  if (!grab_.active()) return;
  grab_.move_cursor(x, y);
  const std::size_t b = grab_.index();
  const std::array<double, 3> v = grab_.release(*session_);
  const sim::BodyState s = session_->bodies()[b];
  const double h = session_->model().spacing;
  char text[160];
  std::snprintf(text, sizeof text, "released body %zu at (%.2f, %.2f, %.2f) with velocity (%.3f, %.3f, %.3f)", b,
                s.x * h, s.y * h, s.z * h, v[0], v[1], v[2]);
  notice(text);
  if (const std::string clamped = session_->clamp_notice(session_->bodies()); !clamped.empty()) notice(clamped);
}

// A floating ball of radius 2 h and the bodies panel's density, its bottom one spacing above the
// water where the cursor points.
void DemoApp::on_drop_ball(double x, double y) {
  const sim::WaterModel& model = session_->model();
  const std::optional<SurfaceHit> hit =
      intersect_surface(pixel_ray(current_camera(), x, y), model, session_->reader().all_displacements());
  if (!hit) {
    notice("no ball dropped: the cursor is not over the water");
    return;
  }
  const double h = model.spacing;
  add_ball({hit->col * h, 3.0 * h, hit->row * h});
}

void DemoApp::add_ball(const std::array<double, 3>& position) {
  const double h = session_->model().spacing;
  const sim::BodySpec ball{.shape = sim::BodyShape::sphere, .motion = sim::BodyMotion::floating, .radius = 2.0 * h,
                           .mass = 0.0, .density = settings_.ball_density, .position = position, .velocity = {},
                           .path = {}};
  try {
    session_->add_body(ball);
  } catch (const InputError& e) {
    notice(std::string("no ball added: ") + e.what());
    return;
  }
  char text[128];
  std::snprintf(text, sizeof text, "body %zu: a ball dropped at (%.2f, %.2f, %.2f)", session_->water().bodies.size() - 1,
                position[0], position[1], position[2]);
  notice(text);
}

void DemoApp::remove_body(std::size_t index) {
  if (index >= session_->water().bodies.size()) {
    notice("no body " + std::to_string(index) + " to remove");
    return;
  }
  session_->remove_body(index);
  grab_.body_removed(index);
  notice("removed body " + std::to_string(index));
}

void DemoApp::apply_requests(const PanelRequests& req) {
  if (req.reset_camera) camera_.reset();
  if (req.rebuild_scene) {
    // The constraints change the model and the land meshes: the session takes them with the water
    // carried over, and a new loop draws its land.
    session_->set_water(apply_modes(base_scene_, settings_.modes));
    build_loop();
    char text[128];
    std::snprintf(text, sizeof text, "border %s, all vertical %s, islands %s",
                  border_name(settings_.modes.border), settings_.modes.all_vertical ? "on" : "off",
                  settings_.modes.islands ? "on" : "off");
    settings_.message = text;
  }
  if (req.switch_solver) {
    sim::SolverChoice s = session_->choice();
    s.gpu = settings_.gpu_solver;
    if (!s.gpu) s.backend = sim::best_backend();
    session_->set_solver(s);
    stats_.solver = solver_label(s);
    settings_.message = "switched to the " + stats_.solver + " (state carried over)";
  }
  if (req.apply_sun) {
    scene::check_sun(settings_.sun);  // the panel's vectors are unit vectors
    session_->set_sun(settings_.sun);
  }
  if (req.apply_physics) {
    try {
      session_->set_physics(settings_.physics);
      settings_.message.clear();
    } catch (const InputError& e) {
      settings_.message = std::string("refused: ") + e.what();
      settings_.physics = session_->water().physics;
    }
  }
  if (req.save_checkpoint) save_checkpoint(settings_.checkpoint_file);
  if (req.load_checkpoint) load_checkpoint(settings_.checkpoint_file);
  if (req.reset_water) {
    session_->reset();
    settings_.message = "water reset";
  }
}

}  // namespace pond::app::demo
