// A session's image (sim/session.h, SessionImage): all that continuing needs beyond its spec.
#include <string>

#include "core/errors.h"
#include "sim/session.h"

namespace pond::sim {

SessionImage Session::image() {
  SessionImage out;
  out.state = state();
  out.steps = solver_->steps_done();
  out.water = water_;
  const double h = water_.grid.spacing;
  for (std::size_t b = 0; b < held_.size() && b < water_.bodies.size(); ++b) {
    if (!held_[b]) continue;  // a held body is saved let go where it is, at rest
    BodySpec spec = *held_[b];
    BodyState& now = out.state.bodies[b];
    const std::array<double, 3> at{now.x * h, now.y * h, now.z * h};
    if (spec.motion == BodyMotion::floating) {
      spec.position = at;
      spec.velocity = {};
    } else {
      spec.path = {PathKey{out.steps, at}};
    }
    now.vx = now.vy = now.vz = 0.0f;
    out.water.bodies[b] = spec;
  }
  out.ripples_until = ripples_until_;
  out.clamp_reported = clamp_reported_;
  out.rain = rain_.image();
  out.wind = wind_.image();
  return out;
}

void Session::restore(const SessionImage& image) {
  const WaterModel& m = model();
  if (image.state.nodes() != m.nodes() || image.state.bodies.size() != m.bodies.size())
    throw InputError("the saved state has " + std::to_string(image.state.nodes()) + " nodes and " +
                     std::to_string(image.state.bodies.size()) + " bodies, its scene " + std::to_string(m.nodes()) +
                     " and " + std::to_string(m.bodies.size()));
  if (image.steps < 0) throw InputError("the saved step count " + std::to_string(image.steps) + " is negative");
  if (image.wind.states.size() != wind_.instances())
    throw InputError("the saved wind has " + std::to_string(image.wind.states.size()) + " trees, its scene " +
                     std::to_string(wind_.instances()));
  rain_.restore(image.rain);
  wind_.restore(image.wind);
  held_.assign(water_.bodies.size(), std::nullopt);
  clamp_reported_ = image.clamp_reported;
  if (wind_spec_.ripples) ripples_until_ = std::max(image.ripples_until, image.steps + 1);
  replace_solver(build(), image.state, image.steps);
}

}  // namespace pond::sim
