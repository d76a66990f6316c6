#pragma once
// The ImGui windows of the demo: the control panel (physics with the stability bound, steps per
// frame, LOD tolerance, splash and rain settings, the wind tree, stats) and the help overlay.
#include "app/demo/demo_settings.h"
#include "render/tree_drawable.h"
#include "sim/session.h"

namespace pond::app::demo {

// What the panel asks the app to do this frame (applied outside ImGui).
struct PanelRequests {
  bool apply_physics = false;  // settings.physics changed
  bool rebuild_scene = false;  // settings.modes changed
  bool switch_solver = false;  // settings.gpu_solver changed
  bool reset_water = false;
  bool reset_camera = false;
  bool apply_sun = false;      // settings.sun changed
  bool save_checkpoint = false;  // to settings.checkpoint_file
  bool load_checkpoint = false;
};

// Builds this frame's windows (between ImGui::NewFrame and ImGui::Render). `tree` is the scene's
// wind tree, or null: its controls act on it and on the session's wind directly (they only change
// what the next frame uses).
PanelRequests draw_panel(DemoSettings& settings, const DemoStats& stats, render::TreeDrawable* tree,
                         sim::Session& session);
void draw_help_overlay(bool& open);

}  // namespace pond::app::demo
