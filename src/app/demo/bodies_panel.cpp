#include "app/demo/bodies_panel.h"

#include <imgui.h>

#include "sim/bodies.h"

namespace pond::app::demo {

BodyRequests draw_bodies_panel(const sim::Session& session, float width, double& ball_density) {
  BodyRequests req;
  constexpr float kWidth = 400;  // a floating body's whole line
  ImGui::SetNextWindowPos(ImVec2(width - kWidth - 10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(kWidth, 0), ImGuiCond_FirstUseEver);
  // Collapsed at first, like the panel's closed sections: on lavapipe every panel pixel costs.
  ImGui::SetNextWindowCollapsed(session.water().bodies.empty(), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("bodies (O: drop a ball)")) {
    ImGui::End();
    return req;
  }
  const auto& bodies = session.water().bodies;
  if (bodies.empty()) ImGui::TextDisabled("no bodies: O drops a ball where the cursor points");
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const sim::BodySpec& spec = bodies[b];
    ImGui::PushID(static_cast<int>(b));
    // The button first: after the text it covered the text's end at the panel's width.
    if (ImGui::SmallButton("remove")) req.remove = b;
    ImGui::SameLine();
    if (session.held(b))
      ImGui::Text("%zu  held (dragged)  r %.2f", b, spec.radius);
    else if (spec.motion == sim::BodyMotion::floating)
      ImGui::Text("%zu  floating  density %.2f  mass %.1f  r %.2f", b,
                  sim::body_density(spec, session.water().physics), sim::body_mass(spec, session.water().physics),
                  spec.radius);
    else
      ImGui::Text("%zu  kinematic  r %.2f", b, spec.radius);
    ImGui::PopID();
  }
  float density = static_cast<float>(ball_density);
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderFloat("ball density", &density, 0.1f, 3.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
    ball_density = density;
  if (ImGui::Button("add ball")) req.add_ball = true;
  ImGui::SameLine();
  ImGui::TextDisabled("left drag a body to move it");
  ImGui::End();
  return req;
}

}  // namespace pond::app::demo
