#pragma once
// A state that today's membrane reaches only with a deep dent or a fast drag, made directly: every
// node of a free 41x41 pool moved 6.5 spacings along -x (so no spring is stretched and nothing
// moves in a step) and 0.2 down, under a kinematic ball of radius 3 held at (20, 0.5, 20). The nodes
// inside the ball rest at columns 24..29, up to 5 columns past a footprint of radius + 1 spacing
// around the ball (columns 16..24): the contact must find them by their actual positions.
#include "scene/scene.h"
#include "sim/model.h"
#include "sim/state.h"

namespace pond::test {

struct ShiftedPool {
  static constexpr int kSize = 41;
  static constexpr float kShift = -6.5f;
  static constexpr int kRow = 20, kCol = 27;  // a node that rests 3 columns past radius + 1: inside
  sim::WaterModel model;
  sim::WaterState state;
};

inline ShiftedPool shifted_pool() {
  scene::Scene s;
  s.grid.rows = s.grid.cols = ShiftedPool::kSize;
  s.border = sim::NodeKind::free;
  sim::BodySpec ball;
  ball.motion = sim::BodyMotion::kinematic;
  ball.radius = 3.0;
  ball.path = {sim::PathKey{0, {20.0, 0.5, 20.0}}};
  s.bodies.push_back(ball);
  ShiftedPool p{sim::build_model(s), {}};
  p.state = sim::rest_state(p.model);
  for (std::size_t n = 0; n < p.state.nodes(); ++n) {
    p.state.ux[n] = ShiftedPool::kShift;
    p.state.uy[n] = -0.2f;
  }
  return p;
}

}  // namespace pond::test
