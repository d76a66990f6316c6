#pragma once
// Wind that also ripples the water (optional, scene "wind.ripples"): the gusts drop small splashes
// ("cat's paws") on the surface. Deterministic: a pure function of the step number, the scene and
// the user wind, so `pond render` gives the same frames every run, for every solver, and the
// demo drops the same ripples as it advances (the session builds them into its model).
//
// Model: every kRippleEverySteps steps, one splash pushing the surface down at a water node drawn
// from a hash of (wind seed, step); its amplitude follows the gust's strength at that moment,
// |gust_target(t)| * kRippleAmplitudePerWind with t = step * dt (the wind clock of pond render), so
// calm air drops nothing and a gust more. Strength 9 gives about 0.14: a tenth of the default
// scene's splash.
#include <cstdint>
#include <vector>

#include "sim/model.h"
#include "sim/water_spec.h"
#include "tree/tree_spec.h"
#include "tree/noise.h"
#include "tree/wind_state.h"

namespace pond::sim {

inline constexpr std::int64_t kRippleEverySteps = 3;
inline constexpr double kRippleAmplitudePerWind = -0.3;  // velocity units per unit of wind
inline constexpr double kRippleRadius = 1.2;             // grid spacings

// The user wind of the scene's "wind" key.
tree::UserWind scene_user_wind(const tree::WindSpec& wind);

// The ripples to apply just before the steps in [first_step, end_step), with their `step` set.
// Nodes that are fixed are never chosen (a ripple lands on water).
std::vector<sim::Perturbation> wind_ripples(const sim::WaterModel& model, const tree::NoiseTable& noise,
                                            const tree::UserWind& user, std::uint64_t seed,
                                            std::int64_t first_step, std::int64_t end_step);

// Appends the wind ripples for steps [0, end_step) to the water's perturbations when wind.ripples
// is set; no-op otherwise.
void add_wind_ripples(WaterSpec& water, const tree::WindSpec& wind, std::int64_t end_step);

}  // namespace pond::sim
