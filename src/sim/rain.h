#pragma once
// Rain on the water: random drops, a given number a frame on average (the fraction carried over),
// each a velocity splash. Deterministic (a fixed seed), so a scripted run rains the same drops.
#include <random>
#include <string>
#include <vector>

#include "sim/model.h"
#include "sim/water_spec.h"

namespace pond::sim {

class Rain {
 public:
  // This frame's drops on `model`'s grid (away from its border), each of `radius` (world units)
  // and an amplitude between 0.5 and 1.5 times `amplitude` (world units of velocity).
  std::vector<Perturbation> drops(const WaterModel& model, double drops_per_frame, double radius, double amplitude);

  // Where the drops stand (for a checkpoint): the generator's state in the standard library's text
  // form (the same on every platform) and the fraction of a drop carried over. restore() throws
  // InputError for a text that is not a generator's state.
  struct Image {
    std::string engine;
    double carry = 0;
  };
  Image image() const;
  void restore(const Image& image);

 private:
  std::mt19937 rng_{12345};
  double carry_ = 0;
};

}  // namespace pond::sim
