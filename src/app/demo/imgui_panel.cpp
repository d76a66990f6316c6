#include "app/demo/imgui_panel.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>

#include "app/demo/controls.h"
#include "sim/stability.h"

namespace pond::app::demo {
namespace {

bool input_double(const char* label, double& value, double step, const char* format) {
  return ImGui::InputDouble(label, &value, step, step * 10, format);
}

// The wind tree: the same controls as right drag, keys 1-9 and double-click.
void draw_tree_section(render::TreeDrawable& tree, sim::Session& session) {
  if (!ImGui::CollapsingHeader("Wind tree")) return;
  float strength = static_cast<float>(session.wind().spec().strength);
  if (ImGui::SliderFloat("wind strength (1-9)", &strength, 0.0f, 9.0f, "%.1f")) session.set_wind_strength(strength);
  float direction = static_cast<float>(session.wind().spec().direction_deg);
  if (ImGui::SliderFloat("wind direction (right drag)", &direction, -180.0f, 180.0f, "%.0f deg"))
    session.set_wind_direction(direction * std::numbers::pi / 180.0);
  int bend = tree.spec().bend == tree::TreeBend::article ? 0 : 1;
  ImGui::Text("bend:");
  ImGui::SameLine();
  bool bend_changed = ImGui::RadioButton("article", &bend, 0);
  ImGui::SameLine();
  bend_changed |= ImGui::RadioButton("keep length", &bend, 1);
  if (bend_changed) tree.set_bend_mode(bend == 0 ? tree::TreeBend::article : tree::TreeBend::keep_length);
  int draw = tree.spec().draw == tree::TreeDraw::lines ? 0 : 1;
  ImGui::Text("draw:");
  ImGui::SameLine();
  bool draw_changed = ImGui::RadioButton("lines", &draw, 0);
  ImGui::SameLine();
  draw_changed |= ImGui::RadioButton("tubes", &draw, 1);
  if (draw_changed) tree.set_draw_mode(draw == 0 ? tree::TreeDraw::lines : tree::TreeDraw::tubes);
  bool leaves = tree.spec().leaves;
  if (ImGui::Checkbox("leaves", &leaves)) tree.set_leaves(leaves);
  ImGui::SameLine();
  if (ImGui::Button("new tree (double-click)")) tree.regrow(tree.spec().seed + 1);
}

// The light: the direction toward the sun as azimuth (from +x toward +z) and elevation above the
// water, in degrees; the vector is rebuilt from them only when one is moved.
bool edit_sun(std::array<double, 3>& sun) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  const double horizontal = std::hypot(sun[0], sun[2]);
  float azimuth = static_cast<float>(std::atan2(sun[2], sun[0]) * kDeg);
  float elevation = static_cast<float>(std::atan2(sun[1], horizontal) * kDeg);
  bool changed = ImGui::SliderFloat("sun azimuth", &azimuth, -180.0f, 180.0f, "%.0f deg");
  changed |= ImGui::SliderFloat("sun elevation", &elevation, 1.0f, 90.0f, "%.0f deg");
  if (changed) {
    const double a = azimuth / kDeg, e = elevation / kDeg;
    sun = {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
  }
  return changed;
}

}  // namespace

PanelRequests draw_panel(DemoSettings& s, const DemoStats& stats, render::TreeDrawable* tree, sim::Session& session) {
  PanelRequests req;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
  // Opaque (the style's): the panel hides the scene behind it by depth (imgui_renderer.h). The
  // stats and the physics open, the other sections closed: on lavapipe every pixel of the panel
  // is a blended, textured fragment, so a fully open panel costs a noticeable part of a frame
  // (docs/perf.md); a click opens what is needed.
  if (!ImGui::Begin("pond (H: keys)", &s.show_panel)) {
    ImGui::End();
    return req;
  }
  ImGui::Text("%.1f FPS  %.2f ms/frame  %dx%d  %s", stats.fps, stats.frame_ms, stats.width, stats.height,
              stats.present_mode.c_str());
  ImGui::Text("simulate %.2f  wait %.2f  LOD %.2f  draw %.2f ms", stats.simulate_ms, stats.last.wait_ms,
              stats.last.lod_ms, stats.last.draw_ms);
  const double share = stats.last.full_triangles ? 100.0 * static_cast<double>(stats.last.triangles) /
                                                       static_cast<double>(stats.last.full_triangles)
                                                 : 0.0;
  ImGui::Text("triangles %zu of %zu (%.1f%%)", stats.last.triangles, stats.last.full_triangles, share);
  ImGui::Text("step %lld  %s  %s", static_cast<long long>(stats.steps_done), stats.solver.c_str(),
              s.paused ? "PAUSED" : "");
  ImGui::TextDisabled("%s", stats.device.c_str());

  if (ImGui::CollapsingHeader("Physics", ImGuiTreeNodeFlags_DefaultOpen)) {
    sim::Physics& p = s.physics;
    bool changed = false;
    changed |= input_double("mass", p.mass, 0.1, "%.3f");
    changed |= input_double("stiffness", p.stiffness, 0.1, "%.3f");
    changed |= input_double("damping", p.damping, 0.01, "%.4f");
    changed |= input_double("dt", p.dt, 0.01, "%.4f");
    int substeps = p.substeps;
    if (ImGui::InputInt("substeps", &substeps)) {
      p.substeps = std::max(1, substeps);
      changed = true;
    }
    // Each substep integrates dt / substeps: that is what must stay under the bound.
    const double bound = (p.mass > 0 && p.stiffness > 0) ? sim::stability_bound(p.mass, p.stiffness, std::max(0.0, p.damping)) : 0;
    const double sub_dt = p.dt / std::max(1, p.substeps);
    const bool stable = sub_dt < bound;
    ImGui::TextColored(stable ? ImVec4(0.6f, 1, 0.6f, 1) : ImVec4(1, 0.4f, 0.4f, 1),
                       "dt/substeps %.4f  stability bound %.4f  %s", sub_dt, bound, stable ? "ok" : "UNSTABLE");
    if (changed) req.apply_physics = true;
    int spf = static_cast<int>(s.steps_per_frame);
    if (ImGui::SliderInt("steps / frame", &spf, 0, 16)) s.steps_per_frame = spf;
    ImGui::Checkbox("paused (Space)", &s.paused);
    ImGui::SameLine();
    if (ImGui::Button("step (N)")) s.step_once = true;
    ImGui::SameLine();
    if (ImGui::Button("reset (R)")) req.reset_water = true;
    if (ImGui::Checkbox("GPU solver (G)", &s.gpu_solver)) req.switch_solver = true;
  }
  if (ImGui::CollapsingHeader("Constraints")) {
    int border = static_cast<int>(s.modes.border);  // NodeKind: free 0, vertical 1, fixed 2
    ImGui::Text("border (B):");
    ImGui::SameLine();
    bool changed = ImGui::RadioButton("free", &border, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("vertical", &border, 1);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("fixed", &border, 2);
    if (changed) s.modes.border = static_cast<sim::NodeKind>(border);
    changed |= ImGui::Checkbox("all vertical (V)", &s.modes.all_vertical);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("islands (I)", &s.modes.islands);
    if (changed) req.rebuild_scene = true;
  }
  if (ImGui::CollapsingHeader("View")) {
    float tau = static_cast<float>(s.lod_tolerance_px);
    if (ImGui::SliderFloat("LOD tau px ([ ])", &tau, 0.0f, 32.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
      s.lod_tolerance_px = tau;
    ImGui::Checkbox("wireframe (W)", &s.wireframe);
    ImGui::SameLine();
    ImGui::Checkbox("vsync (F3)", &s.vsync);
    for (std::size_t k = 0; k < std::size(view::kEffects); ++k) {  // three to a row
      const view::EffectEntry& e = view::kEffects[k];
      if (k % 3 != 0) ImGui::SameLine();
      char label[64];
      std::snprintf(label, sizeof label, "%s (%s)", e.label, e.demo_key);
      ImGui::Checkbox(label, &(s.effects.*e.flag));
    }
    if (ImGui::Button("reset camera (C)")) req.reset_camera = true;
    req.apply_sun = edit_sun(s.sun);
  }
  if (ImGui::CollapsingHeader("Checkpoint")) {  // docs/checkpoints.md
    char name[512];
    std::snprintf(name, sizeof name, "%s", s.checkpoint_file.c_str());
    if (ImGui::InputText("file", name, sizeof name)) s.checkpoint_file = name;
    if (ImGui::Button("save (F5)")) req.save_checkpoint = true;
    ImGui::SameLine();
    if (ImGui::Button("load (F9)")) req.load_checkpoint = true;
  }
  if (ImGui::CollapsingHeader("Splashes")) {
    ImGui::TextDisabled("click: velocity, Shift: position, Ctrl: explosion");
    input_double("radius", s.splash.radius, 0.1, "%.2f");
    input_double("velocity", s.splash.velocity, 0.1, "%.2f");
    input_double("position", s.splash.position, 0.1, "%.2f");
    input_double("explosion", s.splash.explosion, 0.5, "%.2f");
    input_double("explosion radius", s.splash.explosion_radius, 0.1, "%.2f");
    ImGui::Checkbox("rain (D)", &s.rain.on);
    input_double("drops / frame", s.rain.drops_per_frame, 0.1, "%.2f");
    input_double("drop velocity", s.rain.amplitude, 0.1, "%.2f");
  }
  if (tree) draw_tree_section(*tree, session);
  if (!s.message.empty()) ImGui::TextWrapped("%s", s.message.c_str());
  ImGui::End();
  return req;
}

void draw_help_overlay(bool& open) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 10, 10), ImGuiCond_Always, ImVec2(1, 0));
  if (!ImGui::Begin("Keys and mouse", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove)) {
    ImGui::End();
    return;
  }
  if (ImGui::BeginTable("keys", 2)) {
    auto row = [](const char* keys, const char* meaning) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextUnformatted(keys);
      ImGui::TableSetColumnIndex(1);
      ImGui::TextUnformatted(meaning);
    };
    row("left drag", "orbit the camera");
    row("left drag on a body", "move it through the water");
    row("middle drag", "pan");
    row("wheel", "zoom; holding a body: raise or lower it");
    row("left click", "splash (velocity kick)");
    row("Shift+click", "splash (position bump)");
    row("Ctrl+click", "explosion (folds the surface)");
    for (const KeyBinding& b : key_bindings())
      if (*b.keys) row(b.keys, b.meaning);
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace pond::app::demo
