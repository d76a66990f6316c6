#pragma once
// Rain on the water: random drops, a given number a frame on average (the fraction carried over),
// each a velocity splash. Deterministic (a fixed seed), so a scripted run rains the same drops.
#include <random>
#include <vector>

#include "sim/model.h"
#include "sim/water_spec.h"

namespace pond::sim {

class Rain {
 public:
  // This frame's drops on `model`'s grid (away from its border), each of `radius` (world units)
  // and an amplitude between 0.5 and 1.5 times `amplitude` (world units of velocity).
  std::vector<Perturbation> drops(const WaterModel& model, double drops_per_frame, double radius, double amplitude);

 private:
  std::mt19937 rng_{12345};
  double carry_ = 0;
};

}  // namespace pond::sim
