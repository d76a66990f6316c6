#include "app/demo/controls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace pond::app::demo {
namespace {

constexpr double kDragThresholdPx = 4.0;  // a press that moves further is a drag, not a click
constexpr double kDoubleClickSeconds = 0.35;

constexpr KeyBinding kBindings[] = {
    {GLFW_KEY_H, Action::help, "H / F1", "help (this list)"},
    {GLFW_KEY_F1, Action::help, "", ""},
    {GLFW_KEY_F2, Action::panel, "F2", "show / hide the panel"},
    {GLFW_KEY_SPACE, Action::pause, "Space", "pause / run"},
    {GLFW_KEY_N, Action::step, "N", "single step (while paused)"},
    {GLFW_KEY_R, Action::reset_water, "R", "reset the water to rest"},
    {GLFW_KEY_C, Action::reset_camera, "C / Home", "reset the camera"},
    {GLFW_KEY_HOME, Action::reset_camera, "", ""},
    {GLFW_KEY_B, Action::border, "B", "border: fixed -> vertical -> free"},
    {GLFW_KEY_V, Action::all_vertical, "V", "all nodes vertical-only (waves pass through)"},
    {GLFW_KEY_I, Action::islands, "I", "islands on / off"},
    {GLFW_KEY_W, Action::wireframe, "W", "LOD wireframe"},
    {GLFW_KEY_RIGHT_BRACKET, Action::tau_up, "] / =", "LOD tolerance up (coarser)"},
    {GLFW_KEY_EQUAL, Action::tau_up, "", ""},
    {GLFW_KEY_LEFT_BRACKET, Action::tau_down, "[ / -", "LOD tolerance down (0 = full mesh)"},
    {GLFW_KEY_MINUS, Action::tau_down, "", ""},
    {GLFW_KEY_PERIOD, Action::steps_up, ". / ,", "steps per frame up / down"},
    {GLFW_KEY_COMMA, Action::steps_down, "", ""},
    {GLFW_KEY_G, Action::solver, "G", "solver: GPU <-> CPU (state carried over)"},
    {GLFW_KEY_D, Action::rain, "D", "rain (random drops)"},
    {GLFW_KEY_O, Action::drop_ball, "O", "drop a floating ball where the cursor points"},
    {GLFW_KEY_F3, Action::vsync, "F3", "vsync on / off"},
    {GLFW_KEY_F12, Action::screenshot, "F12", "screenshot -> pond-NNNN.png"},
    {GLFW_KEY_F5, Action::save_checkpoint, "F5", "save the pond to the panel's checkpoint file"},
    {GLFW_KEY_F9, Action::load_checkpoint, "F9", "load the pond from that file"},
    {GLFW_KEY_ESCAPE, Action::quit, "Esc", "quit"},
};

// The table above with each effect's toggle (view::kEffects) after the wireframe's row.
std::vector<KeyBinding> with_effects() {
  std::vector<KeyBinding> all(std::begin(kBindings), std::end(kBindings));
  auto at = std::find_if(all.begin(), all.end(), [](const KeyBinding& b) { return b.action == Action::wireframe; }) + 1;
  for (const view::EffectEntry& e : view::kEffects)
    at = all.insert(at, {GLFW_KEY_A + (e.demo_key[0] - 'A'), Action::toggle_effect, e.demo_key, e.meaning, &e}) + 1;
  return all;
}

}  // namespace

std::span<const KeyBinding> key_bindings() {
  static const std::vector<KeyBinding> all = with_effects();
  return all;
}

SplashKind splash_kind(int mods) {
  if (mods & GLFW_MOD_CONTROL) return SplashKind::explosion;
  if (mods & GLFW_MOD_SHIFT) return SplashKind::position;
  return SplashKind::velocity;
}

void InputDispatch::dispatch(const InputEvent& e, bool ui_mouse, bool ui_keyboard, double now, ControlTarget& target) {
  if (e.scripted) ui_mouse = ui_keyboard = false;
  switch (e.kind) {
    case InputEvent::Kind::key: {
      if (ui_keyboard || e.action != GLFW_PRESS) return;
      if (e.code >= GLFW_KEY_1 && e.code <= GLFW_KEY_9) {
        target.on_wind_strength(e.code - GLFW_KEY_0);
        return;
      }
      for (const KeyBinding& b : key_bindings())
        if (b.key == e.code) {
          if (b.action == Action::drop_ball)  // needs the cursor, which only the dispatch knows
            target.on_drop_ball(x_, y_);
          else if (b.effect)
            target.on_toggle_effect(*b.effect);
          else
            target.on_action(b.action);
          return;
        }
      return;
    }
    case InputEvent::Kind::button: {
      if (e.code < 0 || e.code > 2) return;
      const int b = e.code;  // GLFW: 0 left, 1 right, 2 middle
      x_ = e.x, y_ = e.y;
      if (e.action == GLFW_PRESS) {
        if (ui_mouse) return;  // a press on the panel is the panel's
        down_[b] = true, dragged_[b] = false, press_x_[b] = e.x, press_y_[b] = e.y;
        if (b == GLFW_MOUSE_BUTTON_LEFT) grabbing_ = target.on_grab(e.x, e.y);
        return;
      }
      if (!down_[b]) return;
      down_[b] = false;
      if (b == GLFW_MOUSE_BUTTON_LEFT && grabbing_) {  // a held body is let go, no splash
        grabbing_ = false;
        target.on_grab_release(e.x, e.y);
        return;
      }
      if (b == GLFW_MOUSE_BUTTON_LEFT && !dragged_[b]) {
        const bool is_double = now - last_click_time_ < kDoubleClickSeconds &&
                               std::hypot(e.x - last_click_x_, e.y - last_click_y_) < kDragThresholdPx;
        last_click_time_ = is_double ? -1e9 : now, last_click_x_ = e.x, last_click_y_ = e.y;
        if (is_double) {
          target.on_new_tree(e.x, e.y);
        } else {
          target.on_splash(e.x, e.y, splash_kind(e.mods));
        }
      }
      return;
    }
    case InputEvent::Kind::cursor: {
      const double dx = e.x - x_, dy = e.y - y_;
      x_ = e.x, y_ = e.y;
      for (int b = 0; b < 3; ++b)
        if (down_[b] && std::hypot(e.x - press_x_[b], e.y - press_y_[b]) >= kDragThresholdPx) dragged_[b] = true;
      if (grabbing_) target.on_grab_move(e.x, e.y);
      else if (down_[GLFW_MOUSE_BUTTON_LEFT] && dragged_[GLFW_MOUSE_BUTTON_LEFT]) target.on_orbit(dx, dy);
      if (down_[GLFW_MOUSE_BUTTON_MIDDLE] && dragged_[GLFW_MOUSE_BUTTON_MIDDLE]) target.on_pan(dx, dy);
      if (down_[GLFW_MOUSE_BUTTON_RIGHT] && dragged_[GLFW_MOUSE_BUTTON_RIGHT])
        target.on_wind_drag(press_x_[GLFW_MOUSE_BUTTON_RIGHT], press_y_[GLFW_MOUSE_BUTTON_RIGHT], e.x, e.y);
      return;
    }
    case InputEvent::Kind::scroll:
      if (grabbing_) target.on_grab_lift(e.y);  // a held body rises or sinks; the throw keeps it
      else if (!ui_mouse) target.on_zoom(e.y);
      return;
    case InputEvent::Kind::resize:
    case InputEvent::Kind::screenshot:
    case InputEvent::Kind::minimize:
    case InputEvent::Kind::restore:
    case InputEvent::Kind::remove_body:
    case InputEvent::Kind::add_ball:
    case InputEvent::Kind::save:
    case InputEvent::Kind::load:
      return;  // handled by the app (window, swapchain, files), not gestures
  }
}

double next_tolerance(double current_px, bool up) {
  constexpr double kSteps[] = {0, 0.25, 0.5, 1, 2, 4, 8, 16, 32};
  double next = current_px;
  if (up) {
    for (double s : kSteps)
      if (s > current_px + 1e-9) return s;
  } else {
    for (double s : kSteps)
      if (s < current_px - 1e-9) next = s;
  }
  return next;
}

}  // namespace pond::app::demo
