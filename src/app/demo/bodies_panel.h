#pragma once
// The demo's window of the bodies in the water (issues 16, 25): one line per body (its index,
// motion, density and mass, radius; "held" while dragged) with a remove button, the density of the
// balls O and "add ball" drop, and an "add ball" button. A window of
// its own beside the control panel (shown and hidden with it, F2), so the two stay separate files.
#include <cstddef>
#include <optional>

#include "sim/session.h"

namespace pond::app::demo {

// What the window asks the app to do this frame (applied outside ImGui).
struct BodyRequests {
  std::optional<std::size_t> remove;  // remove this body
  bool add_ball = false;              // add a floating ball over the middle of the pond
};

// Builds the window (between ImGui::NewFrame and ImGui::Render) at the top right of a display
// `width` pixels wide.
// `ball_density`: the density of the balls to drop, edited here.
BodyRequests draw_bodies_panel(const sim::Session& session, float width, double& ball_density);

}  // namespace pond::app::demo
