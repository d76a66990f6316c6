#pragma once
// The wind over a scene's trees as time passes: the user's wind (the scene's "wind", edited by the
// demo's controls), the gust noise of its seed, and each tree instance's state (its phase and its
// inertial wind, tree/wind_state.h). No Vulkan: the simulation session owns it and its front end
// moves its clock; the renderer reads the frames the tree's vertex shader bends with.
#include <cstddef>
#include <vector>

#include "tree/bend_mode.h"
#include "tree/noise.h"
#include "tree/tree_spec.h"
#include "tree/wind_state.h"

namespace pond::tree {

// The user wind of a scene's "wind" key (strength, direction in degrees -> radians).
UserWind user_wind(const WindSpec& spec);

class Wind {
 public:
  // For `instances` trees (instance k has phase instance_phase(k)), calm, at time 0.
  Wind(const WindSpec& spec, std::size_t instances);

  void advance(double seconds);            // every instance's gusts and inertia (advance_wind)
  void set_direction(double radians);      // in the xz plane, from +x toward +z
  void set_strength(double strength);      // 0..9, clamped

  const WindSpec& spec() const { return spec_; }  // with the edits
  const UserWind& user() const { return user_; }
  const NoiseTable& noise() const { return noise_; }
  std::size_t instances() const { return states_.size(); }
  // The uniforms instance `k` bends with now (an instance past instances() sways as the last one;
  // without any, calm).
  TreeWindFrame frame(std::size_t k, BendMode mode) const;
  double time() const { return time_; }    // seconds advanced so far

  // Everything that moved since construction from its spec (for a checkpoint): the user's wind
  // with its edits, the clock and each instance's state. restore() takes it back on a Wind made
  // from the same spec and instance count (InternalError otherwise).
  struct Image {
    UserWind user;
    double strength = 0.0, direction_deg = 0.0;  // the spec's edited values
    double time = 0.0;
    std::vector<WindState> states;
  };
  Image image() const { return {user_, spec_.strength, spec_.direction_deg, time_, states_}; }
  void restore(const Image& image);

 private:
  WindSpec spec_;
  UserWind user_;
  NoiseTable noise_;
  std::vector<WindState> states_;
  double time_ = 0.0;
};

}  // namespace pond::tree
