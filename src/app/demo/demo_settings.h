#pragma once
// What the person controls in the demo (keys, panel) and what the panel shows. One struct, so
// the keys, the panel and the frame code read and write the same values.
#include <array>
#include <cstdint>
#include <string>

#include "app/demo/scene_modes.h"
#include "render/frame_loop.h"
#include "scene/scene.h"

namespace pond::app::demo {

struct SplashSettings {
  double radius = 2.0;          // world units (times the grid spacing on use)
  double velocity = -1.5;       // plain click: added to the y velocity (a push down)
  double position = -0.8;       // Shift+click: added to the y position
  double explosion = 6.0;       // Ctrl+click: an upward kick large enough to fold the surface over
  double explosion_radius = 2.5;
};

struct RainSettings {
  bool on = false;
  double drops_per_frame = 0.5;
  double amplitude = -0.6;  // y velocity of a drop
  double radius = 0.8;
};

struct DemoSettings {
  // Simulation
  bool paused = false;
  bool step_once = false;
  std::int64_t steps_per_frame = 1;
  sim::Physics physics;        // edited in the panel, applied with sim::Session::set_physics
  SceneModes modes;
  bool gpu_solver = true;
  // View
  double lod_tolerance_px = 1.0;
  bool wireframe = false;
  view::Effects effects;  // the picture's effects (the scene's view keys, then keys and panel)
  bool vsync = true;
  bool show_panel = true;
  bool show_help = false;
  std::array<double, 3> sun{};  // toward the sun; edited in the panel, applied with sim::Session::set_sun
  SplashSettings splash;
  RainSettings rain;
  double ball_density = 0.5;  // of the balls O and "add ball" drop, relative to water (bodies panel)
  std::string checkpoint_file = "pond.ckpt";  // F5 saves to it, F9 loads it (the panel edits it)
  std::string message;  // the last notice (screenshot saved, unstable parameters refused, …)
};

// Per-frame numbers for the panel.
struct DemoStats {
  double fps = 0;        // smoothed
  double frame_ms = 0;   // smoothed wall time per frame
  render::FrameStats last;  // the frame loop's split of the last frame
  double simulate_ms = 0;   // the last frame's session.advance (the GPU's: recording and submitting)
  std::int64_t steps_done = 0;
  std::string device, solver, present_mode;
  int width = 0, height = 0;
};

}  // namespace pond::app::demo
