#pragma once
// One input event, as the window reports it or as a script replays it. Both sources feed the same
// queue and the same dispatch (controls.cpp), so a script drives exactly what a person does.
// Key, button, action and modifier values are GLFW's (GLFW_KEY_*, GLFW_MOUSE_BUTTON_*, GLFW_PRESS…).
namespace pond::app::demo {

struct InputEvent {
  enum class Kind { key, button, cursor, scroll, resize, screenshot, minimize, restore, remove_body, add_ball, save, load };
  Kind kind = Kind::key;
  int code = 0;     // key: GLFW_KEY_*; button: GLFW_MOUSE_BUTTON_*; remove_body: the body's index
  int action = 0;   // GLFW_PRESS / GLFW_RELEASE / GLFW_REPEAT
  int mods = 0;     // GLFW_MOD_* bits
  double x = 0, y = 0;  // cursor: position (pixels); scroll: offsets; resize: width, height
  bool scripted = false;  // replayed: bypasses the ImGui panel's claim on the mouse and keyboard
  int screenshot = -1;    // screenshot, save, load: index into the script's file names
};

}  // namespace pond::app::demo
