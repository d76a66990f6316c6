#pragma once
// What input means in the demo: the key table (also the help overlay's text) and the one place
// where window and script events become camera moves, splashes and mode changes. Mouse gestures:
// left drag orbits, middle drag pans, the wheel zooms; a left click without drag is a splash.
// Reserved for the wind tree (not bound yet, routed here so adding them is one override each):
// right drag (wind direction and strength), keys 1-9 (wind strength), double-click (a new tree).
#include <span>

#include "app/demo/input_event.h"
#include "view/view_spec.h"

namespace pond::app::demo {

enum class Action {
  quit, help, panel, pause, step, reset_water, reset_camera, border, all_vertical, islands, wireframe,
  tau_up, tau_down, solver, rain, screenshot, vsync, steps_up, steps_down, toggle_effect, drop_ball,
  save_checkpoint, load_checkpoint
};

// The LOD tolerance one step up or down the table 0, 0.25, 0.5, 1, 2, 4, 8, 16, 32 px (keys ] and [).
double next_tolerance(double current_px, bool up);

struct KeyBinding {
  int key;              // GLFW_KEY_*
  Action action;
  const char* keys;     // as shown in the help overlay
  const char* meaning;
  const view::EffectEntry* effect = nullptr;  // Action::toggle_effect: which (view::kEffects)
};
std::span<const KeyBinding> key_bindings();

// Splash modifiers of a click: plain = velocity kick, Shift = position bump, Ctrl = explosion.
enum class SplashKind { velocity, position, explosion };
SplashKind splash_kind(int mods);

// The receiver of dispatched input (DemoApp).
class ControlTarget {
 public:
  virtual ~ControlTarget() = default;
  virtual void on_action(Action action) = 0;
  virtual void on_toggle_effect(const view::EffectEntry& effect) = 0;
  virtual void on_orbit(double dx, double dy) = 0;
  virtual void on_pan(double dx, double dy) = 0;
  virtual void on_zoom(double steps) = 0;
  virtual void on_splash(double x, double y, SplashKind kind) = 0;
  // Reserved for the wind tree: no-ops until it is in the demo.
  virtual void on_wind_drag(double /*x0*/, double /*y0*/, double /*x*/, double /*y*/) {}
  virtual void on_wind_strength(int /*digit 1-9*/) {}
  virtual void on_new_tree(double /*x*/, double /*y*/) {}
  // The bodies in the water: a left press at (x, y) returns true when it grabbed a body (then the
  // left drag moves it and the release lets it go, instead of orbiting or splashing); the drop key
  // drops a floating ball where the cursor is.
  virtual bool on_grab(double /*x*/, double /*y*/) { return false; }
  virtual void on_grab_move(double /*x*/, double /*y*/) {}
  virtual void on_grab_lift(double /*wheel_steps*/) {}
  virtual void on_grab_release(double /*x*/, double /*y*/) {}
  virtual void on_drop_ball(double /*x*/, double /*y*/) {}
};

// Turns events into gestures. Keeps the button and cursor state between events.
class InputDispatch {
 public:
  // `ui_mouse` / `ui_keyboard`: the ImGui panel claims them (ignored for scripted events).
  // `now`: seconds, for double-click detection.
  void dispatch(const InputEvent& e, bool ui_mouse, bool ui_keyboard, double now, ControlTarget& target);

 private:
  bool down_[3] = {false, false, false};  // left, right, middle
  bool dragged_[3] = {false, false, false};
  double press_x_[3] = {}, press_y_[3] = {};
  double x_ = 0, y_ = 0;
  bool grabbing_ = false;  // the left button holds a body (ControlTarget::on_grab)
  double last_click_time_ = -1e9, last_click_x_ = 0, last_click_y_ = 0;
};

}  // namespace pond::app::demo
