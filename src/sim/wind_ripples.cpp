#include "sim/wind_ripples.h"

#include <cmath>
#include <numbers>

namespace pond::sim {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

tree::UserWind scene_user_wind(const tree::WindSpec& wind) {
  tree::UserWind u;
  u.strength = static_cast<float>(wind.strength);
  u.direction = static_cast<float>(wind.direction_deg * std::numbers::pi / 180.0);
  return u;
}

std::vector<sim::Perturbation> wind_ripples(const sim::WaterModel& model, const tree::NoiseTable& noise,
                                            const tree::UserWind& user, std::uint64_t seed,
                                            std::int64_t first_step, std::int64_t end_step) {
  std::vector<sim::Perturbation> out;
  const tree::WindXZ w = tree::user_wind_vector(user);
  const std::int64_t start = (first_step + kRippleEverySteps - 1) / kRippleEverySteps * kRippleEverySteps;
  for (std::int64_t step = std::max<std::int64_t>(start, 0); step < end_step; step += kRippleEverySteps) {
    const tree::WindXZ g = tree::gust_target(noise, w, static_cast<double>(step) * model.physics.dt);
    const double amplitude = kRippleAmplitudePerWind * std::sqrt(double(g.x) * g.x + double(g.z) * g.z);
    if (amplitude == 0.0) continue;
    std::uint64_t h = splitmix64(seed ^ splitmix64(static_cast<std::uint64_t>(step)));
    for (int attempt = 0; attempt < 8; ++attempt, h = splitmix64(h)) {
      const auto row = static_cast<int>((h & 0xffffffffu) % static_cast<std::uint64_t>(model.rows));
      const auto col = static_cast<int>((h >> 32) % static_cast<std::uint64_t>(model.cols));
      if (model.kinds[static_cast<std::size_t>(row) * static_cast<std::size_t>(model.cols) + static_cast<std::size_t>(col)] ==
          static_cast<std::uint8_t>(sim::NodeKind::fixed))
        continue;
      sim::Perturbation p;
      p.step = step;
      p.row = row;
      p.col = col;
      p.radius = kRippleRadius * model.spacing;
      p.amplitude = amplitude;
      out.push_back(p);
      break;
    }
  }
  return out;
}

void add_wind_ripples(WaterSpec& water, const tree::WindSpec& wind, std::int64_t end_step) {
  if (!wind.ripples) return;
  const WaterModel model = build_model(water);
  const std::vector<Perturbation> ripples =
      wind_ripples(model, tree::make_noise_table(wind.seed), scene_user_wind(wind), wind.seed, 0, end_step);
  water.perturbations.insert(water.perturbations.end(), ripples.begin(), ripples.end());
}

}  // namespace pond::sim
