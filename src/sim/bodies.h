#pragma once
// The bodies of a model (sim::BodySpec, built in grid units) and their motion that does not depend
// on the water: a kinematic body's position along its path at any substep, and the bodies' state
// in world units for output. The laws are in shaders/shared/body_*.h; sim/contact.h runs them on
// the CPU, water_contact.comp on the GPU.
#include <array>
#include <cstdint>
#include <vector>

#include "shared/bodies.h"
#include "sim/water_spec.h"

namespace pond::sim {

using shared::BodyState;

struct BodyModel {
  shared::BodyConstants constants{};
  // A kinematic body's keys in grid units: {step, x, y, z}; empty for a floating body.
  std::vector<std::array<double, 4>> path;
  BodyState initial{};  // at step 0
  bool floating() const { return constants.floating != 0u; }
};

// A sphere's volume (world units).
double sphere_volume(double radius);
// A floating body's density relative to water and its mass: from whichever of the two its spec
// gives (BodySpec::density > 0: the density).
double body_density(const BodySpec& body, const Physics& physics);
double body_mass(const BodySpec& body, const Physics& physics);

// The models of `bodies` under `physics` on a grid of spacing h. The specs are valid (src/scene
// checked them).
std::vector<BodyModel> build_bodies(const std::vector<BodySpec>& bodies, const Physics& physics,
                                    double spacing);

// A kinematic body at the end of substep `substep` (of `substeps`) of step `step`: its path's
// position there, rounded once from double, and the velocity of the path's segment (0 outside the
// path's span). `step_dt` is a step's length.
BodyState kinematic_state(const BodyModel& body, std::int64_t step, int substep, int substeps,
                          double step_dt);

// The contract's bodies dump: float32 (B, 6) = x, y, z, vx, vy, vz in world units.
std::vector<float> bodies_to_world(const std::vector<BodyState>& bodies, float spacing);

}  // namespace pond::sim
