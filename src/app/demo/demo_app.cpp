#include "app/demo/demo_app.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <random>

#include "app/demo/app_lifetime.h"
#include "app/demo/bodies_panel.h"
#include "app/demo/body_grab.h"
#include "app/demo/controls.h"
#include "app/demo/demo_settings.h"
#include "app/demo/imgui_panel.h"
#include "app/demo/imgui_renderer.h"
#include "app/demo/orbit_camera.h"
#include "app/demo/picking.h"
#include "app/demo/run_totals.h"
#include "app/demo/scene_modes.h"
#include "app/demo/screenshot.h"
#include "app/demo/script.h"
#include "app/demo/swapchain.h"
#include "app/demo/window.h"
#include "core/errors.h"
#include "core/output_file.h"
#include "gpu/context.h"
#include "render/body_drawable.h"
#include "render/frame_loop.h"
#include "gpu/gpu_solver.h"
#include "render/tree_drawable.h"
#include "scene/scene.h"
#include "sim/backends.h"
#include "sim/session.h"

namespace pond::app::demo {
namespace {

static_assert(Swapchain::kAcquireRing == render::FrameLoop::kFramesInFlight + 1,
              "the acquire-semaphore ring relies on the frame loop's slot fences (swapchain.h)");

std::string solver_label(const sim::SolverChoice& s) {
  return s.gpu ? "GPU solver" : std::string("CPU solver (") + sim::backend_name(s.backend) + ")";
}

class DemoApp final : public ControlTarget {
 public:
  DemoApp(const DemoOptions& options, scene::Scene scene, Script script)
      : options_(options),
        base_scene_(std::move(scene)),
        script_(std::move(script)),
        window_(options.width, options.height, "pond"),
        ctx_(gpu::ContextOptions{.device = options.device, .validation = options.validation}, window_surface(window_)),
        imgui_session_(window_.handle()),
        swapchain_(ctx_, window_.framebuffer_extent(), options.vsync),
        imgui_(ctx_, swapchain_.format()),
        shots_(ctx_),
        idle_{ctx_} {
    settings_.physics = base_scene_.physics;
    settings_.modes = modes_of(base_scene_);
    settings_.steps_per_frame = base_scene_.view.steps_per_frame;
    settings_.lod_tolerance_px = base_scene_.view.lod_tolerance_px;
    settings_.effects = base_scene_.view.effects;
    settings_.sun = base_scene_.lighting.sun;
    settings_.vsync = options.vsync;
    stats_.device = ctx_.device_name();
    if (!swapchain_.can_copy_images() && (!options.screenshot.empty() || !script_.screenshots.empty()))
      throw RuntimeError("this window's swapchain images cannot be read back, so no screenshots can be taken");
    session_ = std::make_unique<sim::Session>(scene_with_settings(), sim::SolverChoice{}, gpu::gpu_solver_factory(ctx_));
    stats_.solver = solver_label(session_->choice());
    build_loop();
    const vk::Extent2D e = swapchain_.extent();
    camera_.set_home(loop_->default_camera(static_cast<int>(e.width), static_cast<int>(e.height)));
  }

  int run();

  // ControlTarget
  void on_action(Action action) override;
  void on_orbit(double dx, double dy) override { camera_.orbit(dx, dy); }
  void on_pan(double dx, double dy) override { camera_.pan(dx, dy, static_cast<int>(swapchain_.extent().height)); }
  void on_zoom(double steps) override { camera_.zoom(steps); }
  void on_splash(double x, double y, SplashKind kind) override;
  // The wind tree (when the scene has one): right drag, keys 1-9, double-click.
  void on_wind_drag(double x0, double y0, double x, double y) override;
  void on_wind_strength(int digit) override {
    if (tree_) tree_->set_strength(digit);
  }
  void on_new_tree(double /*x*/, double /*y*/) override {
    if (tree_) tree_->regrow(tree_->spec().seed + 1);
  }
  // The bodies in the water: left drag on one, the drop key, the bodies window, script events.
  bool on_grab(double x, double y) override;
  void on_grab_move(double x, double y) override { grab_.move_cursor(x, y); }
  void on_grab_release(double x, double y) override;
  void on_drop_ball(double x, double y) override;

 private:
  static gpu::WindowSurface window_surface(const Window& window) {
    return gpu::WindowSurface{.instance_extensions = Window::required_instance_extensions(),
                              .make_surface = [&window](VkInstance instance) { return window.create_surface(instance); }};
  }
  scene::Scene scene_with_settings() const;  // the scene with the demo's modes and edits
  void build_loop();
  void apply_requests(const PanelRequests& req);
  void make_rain();
  void add_ball(const std::array<double, 3>& position);
  std::array<double, 3> middle_of_pond() const {  // where the bodies window adds a ball
    const sim::WaterModel& m = session_->model();
    return {0.5 * (m.cols - 1) * m.spacing, 3.0 * m.spacing, 0.5 * (m.rows - 1) * m.spacing};
  }
  void remove_body(std::size_t index);
  void notice(const std::string& text);  // the panel's message, and stdout unless --quiet
  void draw_ui();
  bool draw_frame(const std::string* screenshot_path);  // false: swapchain out of date, retry
  lod::Camera current_camera() const {
    const vk::Extent2D e = swapchain_.extent();
    return camera_.camera(static_cast<int>(e.width), static_cast<int>(e.height));
  }
  void take_screenshot_next(std::string path) { pending_shot_ = std::move(path); }

  DemoOptions options_;
  scene::Scene base_scene_;
  Script script_;
  // Dependency order: destroyed bottom-up (the loop before the drawable it draws, everything
  // Vulkan before the context, the context's surface before the window, the window before GLFW).
  GlfwSession glfw_;
  Window window_;
  gpu::Context ctx_;
  ImGuiSession imgui_session_;
  Swapchain swapchain_;
  ImGuiRenderer imgui_;
  ScreenshotWriter shots_;
  std::unique_ptr<sim::Session> session_;  // the water: splashes, edits, solver switches go here
  std::unique_ptr<render::FrameLoop> loop_;
  std::optional<render::TreeDrawable> tree_;  // the scene's wind tree; waits for the device when destroyed
  std::optional<render::BodyDrawable> bodies_;  // the session's bodies; waits for the device when destroyed
  IdleBeforeTeardown idle_;

  DemoSettings settings_;
  DemoStats stats_;
  OrbitCamera camera_;
  InputDispatch input_;
  BodyGrab grab_;
  std::optional<std::string> pending_shot_;
  int shot_counter_ = 0;
  bool quit_ = false;
  std::int64_t frame_ = 0;  // the frame being prepared (notices name it)
  double rain_carry_ = 0;
  double acquire_ms_ = 0, present_ms_ = 0;  // the last frame's waits in the swapchain
  std::mt19937 rng_{12345};  // deterministic rain: scripted runs repeat
};

scene::Scene DemoApp::scene_with_settings() const {
  scene::Scene scene = apply_modes(base_scene_, settings_.modes);
  scene.physics = settings_.physics;
  scene.lighting.sun = settings_.sun;
  return scene;
}

// A loop for the session's current model (its land follows the constraints); the tree with the
// controls' changes carried over.
void DemoApp::build_loop() {
  if (loop_) loop_->wait_idle();
  loop_.reset();  // one loop at a time: its buffers and pipelines are the big allocations
  loop_ = std::make_unique<render::FrameLoop>(ctx_, *session_, swapchain_.format());
  loop_->set_sun(settings_.sun);
  const scene::Scene& scene = session_->scene();
  if (scene.tree) {  // drawn before the UI
    const tree::TreeSpec spec = tree_ ? tree_->spec() : *scene.tree;
    const tree::WindSpec wind = tree_ ? tree_->wind() : scene.wind;
    tree_.reset();
    tree_.emplace(ctx_, *loop_, spec, wind);
    tree_->set_manual_clock();  // the water runs faster than real time; the wind runs in real time
    loop_->add_drawable(*tree_);
  }
  bodies_.reset();
  bodies_.emplace(ctx_, *loop_);
  loop_->add_drawable(*bodies_);
  loop_->add_drawable(imgui_);
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
    case Action::reflections: settings_.effects.reflections = !settings_.effects.reflections; break;
    case Action::caustics: settings_.effects.caustics = !settings_.effects.caustics; break;
    case Action::shadows: settings_.effects.shadows = !settings_.effects.shadows; break;
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
  tree_->set_wind_direction(std::atan2(wz, wx));
}

void DemoApp::on_splash(double x, double y, SplashKind kind) {
  const sim::WaterModel& model = session_->model();
  const sim::WaterState state = session_->state();  // rare (a click): the copy is fine
  const std::optional<SurfaceHit> hit = intersect_surface(pixel_ray(current_camera(), x, y), model, state);
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
}

// A floating ball of radius 2 h and mass 30 (the scenes' balls), its bottom one spacing above the
// water where the cursor points.
void DemoApp::on_drop_ball(double x, double y) {
  const sim::WaterModel& model = session_->model();
  const sim::WaterState state = session_->state();  // rare (a key): the copy is fine
  const std::optional<SurfaceHit> hit = intersect_surface(pixel_ray(current_camera(), x, y), model, state);
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
                           .mass = 30.0, .position = position, .velocity = {}, .path = {}};
  try {
    session_->add_body(ball);
  } catch (const InputError& e) {
    notice(std::string("no ball added: ") + e.what());
    return;
  }
  char text[128];
  std::snprintf(text, sizeof text, "body %zu: a ball dropped at (%.2f, %.2f, %.2f)", session_->scene().bodies.size() - 1,
                position[0], position[1], position[2]);
  notice(text);
}

void DemoApp::remove_body(std::size_t index) {
  if (index >= session_->scene().bodies.size()) {
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
    loop_->set_sun(settings_.sun);
  }
  if (req.apply_physics) {
    try {
      session_->set_physics(settings_.physics);
      settings_.message.clear();
    } catch (const InputError& e) {
      settings_.message = std::string("refused: ") + e.what();
      settings_.physics = session_->scene().physics;
    }
  }
  if (req.reset_water) {
    session_->reset();
    settings_.message = "water reset";
  }
}

void DemoApp::make_rain() {
  if (!settings_.rain.on) return;
  const sim::WaterModel& model = session_->model();
  std::uniform_real_distribution<double> row(1, model.rows - 2), col(1, model.cols - 2), scale(0.5, 1.5);
  rain_carry_ += settings_.rain.drops_per_frame;
  for (; rain_carry_ >= 1; rain_carry_ -= 1)
    session_->splash(sim::Perturbation{.row = row(rng_), .col = col(rng_),
                                    .radius = settings_.rain.radius * model.spacing,
                                    .amplitude = settings_.rain.amplitude * scale(rng_) * model.spacing});
}

void DemoApp::draw_ui() {
  ImGui_ImplGlfw_NewFrame();
  // Scripted runs and resizes: ImGui's display size follows the swapchain, not the window query.
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(swapchain_.extent().width), static_cast<float>(swapchain_.extent().height));
  io.DisplayFramebufferScale = ImVec2(1, 1);
  ImGui::NewFrame();
  PanelRequests req;
  if (settings_.show_panel) req = draw_panel(settings_, stats_, tree_ ? &*tree_ : nullptr);
  BodyRequests bodies;
  if (settings_.show_panel) bodies = draw_bodies_panel(*session_, io.DisplaySize.x);
  if (settings_.show_help) draw_help_overlay(settings_.show_help);
  ImGui::Render();
  apply_requests(req);
  if (bodies.remove) remove_body(*bodies.remove);
  if (bodies.add_ball) add_ball(middle_of_pond());
}

bool DemoApp::draw_frame(const std::string* screenshot_path) {
  using Clock = std::chrono::steady_clock;
  // The frame's compute and LOD first, then the swapchain image: acquiring waits for the window
  // system to have taken the last frame (frame_loop.h), which this way overlaps with them. A frame
  // simulated before a failed acquire is drawn after the swapchain's recreation.
  if (!loop_->simulated()) {
    std::int64_t steps = settings_.paused ? 0 : settings_.steps_per_frame;
    if (settings_.step_once) steps = std::max<std::int64_t>(steps, 1), settings_.step_once = false;
    const render::FrameView view{.camera = current_camera(), .lod_tolerance_px = settings_.lod_tolerance_px,
                              .wireframe = settings_.wireframe, .steps = steps, .effects = settings_.effects};
    grab_.drag(*session_, view.camera, steps);  // a held body toward the cursor over these steps
    loop_->simulate(view, swapchain_.extent());
  }
  const Clock::time_point t0 = Clock::now();
  const std::optional<AcquiredImage> image = swapchain_.acquire();
  acquire_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  if (!image) return false;
  const vk::Extent2D extent = swapchain_.extent();
  const bool shot = screenshot_path != nullptr;
  const render::FrameTarget target{.image = image->image, .view = image->view, .format = swapchain_.format(),
                                .extent = extent, .old_layout = vk::ImageLayout::eUndefined,
                                .final_layout = shot ? vk::ImageLayout::eTransferSrcOptimal : vk::ImageLayout::ePresentSrcKHR,
                                .wait_semaphore = image->acquired,
                                .signal_semaphore = shot ? shots_.drawn() : image->rendered};
  stats_.last = loop_->draw(target);
  stats_.steps_done = session_->steps_done();
  if (shot) {
    shots_.save(image->image, swapchain_.format(), extent, image->rendered, *screenshot_path);
    settings_.message = "saved " + *screenshot_path;
  }
  const Clock::time_point t1 = Clock::now();
  const bool current = swapchain_.present(*image);
  present_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - t1).count();
  if (!current) swapchain_.recreate(window_.framebuffer_extent(), settings_.vsync);
  return true;
}

int DemoApp::run() {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  Clock::time_point last = start;
  std::size_t next_event = 0;
  std::int64_t frame = 0, minimized_frames = 0;
  RunTotals totals;
  while (!quit_ && (options_.frames == 0 || frame < options_.frames)) {
    frame_ = frame;
    window_.poll();
    if (window_.should_close()) break;
    // This frame's script events join the window's, in the same dispatch.
    std::vector<InputEvent>& events = window_.events();
    for (; next_event < script_.events.size() && script_.events[next_event].frame <= frame; ++next_event) {
      const InputEvent& e = script_.events[next_event].event;
      if (e.kind == InputEvent::Kind::resize) {
        window_.set_size(static_cast<int>(e.x), static_cast<int>(e.y));
      } else if (e.kind == InputEvent::Kind::minimize) {
        window_.minimize();
      } else if (e.kind == InputEvent::Kind::restore) {
        window_.restore();
      } else if (e.kind == InputEvent::Kind::screenshot) {
        take_screenshot_next(script_.screenshots[static_cast<std::size_t>(e.screenshot)]);
      } else if (e.kind == InputEvent::Kind::remove_body) {
        remove_body(static_cast<std::size_t>(e.code));
      } else if (e.kind == InputEvent::Kind::add_ball) {
        add_ball(middle_of_pond());
      } else {
        events.push_back(e);
      }
    }
    const ImGuiIO& io = ImGui::GetIO();
    const double now = glfwGetTime();
    for (const InputEvent& e : events) input_.dispatch(e, io.WantCaptureMouse, io.WantCaptureKeyboard, now, *this);
    events.clear();
    if (quit_) break;

    // Minimized: draw nothing and sleep until something happens (at most 0.1 s). The frame still
    // counts, so --frames ends and a script's later events (a restore) still come.
    if (window_.minimized()) {
      window_.wait(0.1);
      ++minimized_frames;
      ++frame;
      continue;
    }
    const vk::Extent2D fb = window_.framebuffer_extent();
    if (fb != swapchain_.extent() || settings_.vsync != swapchain_.vsync()) swapchain_.recreate(fb, settings_.vsync);
    stats_.width = static_cast<int>(swapchain_.extent().width);
    stats_.height = static_cast<int>(swapchain_.extent().height);
    stats_.present_mode = vk::to_string(swapchain_.present_mode());

    make_rain();
    if (tree_) tree_->advance_clock(stats_.frame_ms / 1000.0);  // the previous frame's wall time
    draw_ui();
    const bool last_frame = options_.frames > 0 && frame + 1 == options_.frames;
    std::optional<std::string> shot = std::move(pending_shot_);
    pending_shot_.reset();
    if (last_frame && !options_.screenshot.empty()) shot = options_.screenshot;
    if (!draw_frame(shot ? &*shot : nullptr)) {
      swapchain_.recreate(window_.framebuffer_extent(), settings_.vsync);
      if (shot) pending_shot_ = std::move(shot);
      continue;
    }
    const Clock::time_point t = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(t - last).count();
    last = t;
    stats_.frame_ms = totals.drawn == 0 ? ms : 0.9 * stats_.frame_ms + 0.1 * ms;
    stats_.fps = stats_.frame_ms > 0 ? 1000.0 / stats_.frame_ms : 0;
    totals.add(ms, stats_.last, acquire_ms_, present_ms_);
    ++frame;
  }
  loop_->wait_idle();
  ctx_.device().waitIdle();
  if (minimized_frames > 0 && !options_.quiet)
    std::printf("pond demo: %lld of %lld frames minimized (nothing drawn)\n", static_cast<long long>(minimized_frames),
                static_cast<long long>(frame));
  if (!options_.screenshot.empty() && window_.minimized() && options_.frames > 0)
    throw RuntimeError("the window was minimized at the last frame: no screenshot for " + options_.screenshot);
  if (!options_.quiet)
    totals.print(swapchain_.extent().width, swapchain_.extent().height, ctx_.device_name(), stats_.solver,
                 stats_.present_mode, stats_.last.full_triangles);
  if (options_.validation && ctx_.validation_log().count() > 0)
    throw RuntimeError(std::to_string(ctx_.validation_log().count()) + " Vulkan validation message(s) were logged (see above)");
  return 0;
}

}  // namespace

int run_demo(const DemoOptions& options) {
  // Bad input first, before any window: exit 2 even on a machine without a display.
  scene::Scene scene = scene::load_scene(options.scene);
  Script script = load_script(options.script);
  if (!options.screenshot.empty()) check_output_path(options.screenshot);
  DemoApp app(options, std::move(scene), std::move(script));
  return app.run();
}

}  // namespace pond::app::demo
