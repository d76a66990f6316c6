#pragma once
// The demo application (demo_app.h runs it): its parts in dependency order, the frame (demo_app.cpp)
// and what input does to the session and the view (demo_input.cpp). It steps the session; the
// frame loop draws it read only.
#include <chrono>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/demo/app_lifetime.h"
#include "app/demo/body_grab.h"
#include "app/demo/controls.h"
#include "app/demo/demo_app.h"
#include "app/demo/demo_settings.h"
#include "app/demo/imgui_panel.h"
#include "app/demo/gpu_stack.h"
#include "app/demo/imgui_renderer.h"
#include "app/demo/run_totals.h"
#include "app/demo/orbit_camera.h"
#include "app/demo/screenshot.h"
#include "app/demo/script.h"
#include "app/demo/swapchain.h"
#include "app/demo/window.h"
#include "core/errors.h"
#include "render/body_drawable.h"
#include "render/frame_loop.h"
#include "render/tree_drawable.h"
#include "scene/scene.h"
#include "sim/session.h"

namespace pond::app::demo {

// "GPU solver" or "CPU solver (avx2)": the panel's and the notices' name for a choice.
std::string solver_label(const sim::SolverChoice& s);

// The demo's device and what lives on it (gpu_stack.h); an allocation that fails while making it
// is tried once more (a real shortage fails again and ends the demo with its line).
std::unique_ptr<GpuStack> make_gpu_stack(const DemoOptions& options, const Window& window, bool vsync,
                                         const FirstExtent& extent);

class DemoApp final : public ControlTarget {
 public:
  DemoApp(const DemoOptions& options, scene::Scene scene, Script script);
  ~DemoApp();
  int run();

  // ControlTarget (demo_input.cpp)
  void on_action(Action action) override;
  void on_toggle_effect(const view::EffectEntry& effect) override;
  void on_orbit(double dx, double dy) override { camera_.orbit(dx, dy); }
  void on_pan(double dx, double dy) override { camera_.pan(dx, dy, static_cast<int>(gpu_->swapchain.extent().height)); }
  void on_zoom(double steps) override { camera_.zoom(steps); }
  void on_splash(double x, double y, SplashKind kind) override;
  // The wind tree (when the scene has one): right drag, keys 1-9, double-click.
  void on_wind_drag(double x0, double y0, double x, double y) override;
  void on_wind_strength(int digit) override {
    if (tree_) session_->set_wind_strength(digit);
  }
  void on_new_tree(double /*x*/, double /*y*/) override {
    if (tree_) tree_->regrow(tree_->spec().seed + 1);
  }
  // The bodies in the water: left drag on one, the drop key, the bodies window, script events.
  bool on_grab(double x, double y) override;
  void on_grab_move(double x, double y) override { grab_.move_cursor(x, y); }
  void on_grab_lift(double wheel_steps) override { grab_.lift(wheel_steps * session_->model().spacing); }
  void on_grab_release(double x, double y) override;
  void on_drop_ball(double x, double y) override;

 private:
  scene::Scene scene_with_settings() const;  // the scene with the demo's modes and edits
  // A session for `scene` on the chosen solver, continuing `image` when given.
  void adopt_scene_settings();  // the panel's physics, modes, view and sun from base_scene_
  void make_session(const scene::Scene& scene, const sim::SessionImage* image);
  void build_loop();
  void apply_requests(const PanelRequests& req);
  void add_ball(const std::array<double, 3>& position);
  std::array<double, 3> middle_of_pond() const;  // where the bodies window adds a ball
  void remove_body(std::size_t index);
  void notice(const std::string& text);  // the panel's message, and stdout unless --quiet
  void handle_script_events(std::int64_t frame, std::size_t& next_event);
  void draw_ui();
  bool draw_frame(const std::vector<std::string>& shots);  // false: swapchain out of date, retry
  void step();  // the session by this frame's steps (after presenting)
  // One frame's work on the device (what run() loops over); false: the swapchain was out of date.
  bool frame_on_device(std::int64_t frame, std::int64_t& minimized_frames, RunTotals& totals,
                       std::chrono::steady_clock::time_point& last);
  // After `failure` (a lost device, memory short: device_recovery.cpp): the water goes on on the
  // CPU, the device and everything on it are made again, then the GPU solver comes back.
  void recover(const GpuFailure& failure);
  // The pond saved to / loaded from a checkpoint file (demo_checkpoint.cpp).
  void save_checkpoint(const std::string& path);
  void load_checkpoint(const std::string& path);
  lod::Camera current_camera() const {
    const vk::Extent2D e = gpu_->swapchain.extent();
    return camera_.camera(static_cast<int>(e.width), static_cast<int>(e.height));
  }
  void take_screenshot_next(std::string path) { pending_shots_.push_back(std::move(path)); }
  // Throws RuntimeError naming the first requested screenshot (--screenshot, a script's) never
  // written: the demo ended (ESCAPE, the window closed, minimized) before its frame was drawn.
  void check_screenshots_written(std::int64_t frames_run) const;

  DemoOptions options_;
  scene::Scene base_scene_;
  Script script_;
  // Dependency order: destroyed bottom-up (the loop before the drawable it draws, everything
  // Vulkan before the context, the context's surface before the window, the window before GLFW).
  GlfwSession glfw_;
  Window window_;
  ImGuiSession imgui_session_;
  std::unique_ptr<GpuStack> gpu_;          // the device and what lives on it; made again after a loss
  std::unique_ptr<sim::Session> session_;  // the water: steps, splashes, edits, solver switches go here
  scene::Scene drawn_scene_;               // the scene the loop shows (the modes applied)
  std::unique_ptr<render::FrameLoop> loop_;
  std::optional<render::TreeDrawable> tree_;    // the scene's wind tree; waits for the device when destroyed
  std::optional<render::BodyDrawable> bodies_;  // the session's bodies; waits for the device when destroyed

  DemoSettings settings_;
  DemoStats stats_;
  OrbitCamera camera_;
  InputDispatch input_;
  BodyGrab grab_;
  std::vector<std::string> pending_shots_;  // the next drawn frame's (F12, the script's)
  std::set<std::string> written_;            // every screenshot saved
  int shot_counter_ = 0;
  bool quit_ = false;
  std::int64_t frame_ = 0;  // the frame being prepared (notices name it)
  double acquire_ms_ = 0, present_ms_ = 0;  // the last frame's waits in the swapchain
  int recoveries_ = 0;                      // devices made again without a good frame between
  std::size_t earlier_validation_messages_ = 0;  // logged on devices since made again
};

}  // namespace pond::app::demo
