#include "sim/model.h"

#include <algorithm>
#include <cmath>

#include "shared/exact_math.h"
#include "sim/basin.h"
#include "sim/exact_exp.h"

namespace pond::sim {

static_assert(static_cast<unsigned>(NodeKind::free) == shared::kNodeFree &&
              static_cast<unsigned>(NodeKind::vertical) == shared::kNodeVertical &&
              static_cast<unsigned>(NodeKind::fixed) == shared::kNodeFixed);

namespace {

// The float nearest `nominal` for which at_rest(L) holds, searching outward; `nominal` when none
// within 64 ulps does (not reached for the rest lengths pond uses: tested).
template <class AtRest>
float nearest_rest_length(float nominal, AtRest at_rest) {
  float up = nominal, down = nominal;
  for (int k = 0; k < 64; ++k) {
    if (at_rest(up)) return up;
    if (at_rest(down)) return down;
    up = std::nextafter(up, 2 * nominal);
    down = std::nextafter(down, 0.0f);
  }
  return nominal;
}

}  // namespace

float calibrated_rest_length(float nominal, float rest_l2, int rsqrt_steps) {
  // A length whose product with the approximate rsqrt(rest_l2) rounds to 1.
  return nearest_rest_length(nominal,
                             [&](float l) { return shared::spring_factor(rest_l2, l, rsqrt_steps) == 0.0f; });
}

float calibrated_rest_length_accurate(float nominal, float rest_l2) {
  const float y = static_cast<float>(1.0 / std::sqrt(static_cast<double>(rest_l2)));
  return nearest_rest_length(nominal, [y](float l) { return 1.0f - l * y == 0.0f; });
}

std::pair<float, float> gpu_rest_lengths(const WaterModel& m) {
  const StepConstants& k = m.constants;
  if (m.math != MathMode::fast || static_cast<float>(m.physics.rest_ratio) != 1.0f) return {k.rest_edge, k.rest_diag};
  return {calibrated_rest_length_accurate(1.0f, 1.0f),
          calibrated_rest_length_accurate(static_cast<float>(std::sqrt(2.0)), 2.0f)};
}

PerturbationTable tabulate(const Perturbation& p, const WaterModel& m) {
  PerturbationTable t;
  t.step = p.step;
  t.target = p.target;
  t.mode = p.mode;
  const double h = m.spacing;
  const double reach = 3.0 * p.radius / h;  // in index units
  // Clamped to the grid before the conversion to int: a radius far beyond the grid reaches all of it.
  const double last_row = m.rows - 1, last_col = m.cols - 1;
  const int i0 = static_cast<int>(std::clamp(std::ceil(p.row - reach), 0.0, last_row));
  const int i1 = static_cast<int>(std::clamp(std::floor(p.row + reach), 0.0, last_row));
  const int j0 = static_cast<int>(std::clamp(std::ceil(p.col - reach), 0.0, last_col));
  const int j1 = static_cast<int>(std::clamp(std::floor(p.col + reach), 0.0, last_col));
  const double limit2 = 9.0 * p.radius * p.radius;
  for (int i = i0; i <= i1; ++i)
    for (int j = j0; j <= j1; ++j) {
      const std::size_t n = static_cast<std::size_t>(i) * m.cols + j;
      if (m.kinds[n] == static_cast<std::uint8_t>(NodeKind::fixed)) continue;
      const double di = (i - p.row) * h, dj = (j - p.col) * h;
      const double d2 = di * di + dj * dj;
      if (d2 > limit2) continue;
      const double w = p.amplitude * exact_exp(-d2 / (2.0 * p.radius * p.radius));
      t.nodes.push_back(static_cast<std::uint32_t>(n));
      t.weights.push_back(static_cast<float>(w / h));
    }
  return t;
}

std::vector<std::uint8_t> node_kinds(const WaterSpec& s) {
  const int rows = s.grid.rows, cols = s.grid.cols;
  std::vector<std::uint8_t> kinds(static_cast<std::size_t>(rows) * cols, static_cast<std::uint8_t>(NodeKind::free));
  auto constrain = [&](int i, int j, NodeKind kind) {
    auto& n = kinds[static_cast<std::size_t>(i) * cols + j];
    n = std::max(n, static_cast<std::uint8_t>(kind));
  };
  if (s.border != NodeKind::free)
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j)
        if (i == 0 || j == 0 || i == rows - 1 || j == cols - 1) constrain(i, j, s.border);
  for (const ConstraintRect& c : s.constraints)
    for (int i = c.row0; i <= c.row1; ++i)
      for (int j = c.col0; j <= c.col1; ++j) constrain(i, j, c.kind);
  return kinds;
}

WaterModel build_model(const WaterSpec& s, MathMode math) {
  WaterModel m;
  m.rows = s.grid.rows;
  m.cols = s.grid.cols;
  m.spacing = static_cast<float>(s.grid.spacing);
  m.substeps = s.physics.substeps;
  m.math = math;
  m.physics = s.physics;

  const Physics& p = s.physics;
  const double dt = p.dt / p.substeps;
  StepConstants& k = m.constants;
  k.kc = static_cast<float>(p.stiffness * dt / p.mass);
  k.kd = static_cast<float>(p.damping * dt / p.mass);
  k.dt = static_cast<float>(dt);
  k.rsqrt_steps = math == MathMode::exact ? shared::kRsqrtStepsExact : shared::kRsqrtStepsFast;
  const float ratio = static_cast<float>(p.rest_ratio);
  const float edge = ratio, diag = static_cast<float>(p.rest_ratio * std::sqrt(2.0));
  // At rest an edge spring has l2 = 1 and a diagonal one l2 = 1 + 1 + 0 = 2 exactly.
  k.rest_edge = ratio == 1.0f ? calibrated_rest_length(edge, 1.0f, k.rsqrt_steps) : edge;
  k.rest_diag = ratio == 1.0f ? calibrated_rest_length(diag, 2.0f, k.rsqrt_steps) : diag;

  m.basin = s.basin;
  m.kinds = node_kinds(s);
  m.land = land_runs(m.kinds, m.rows, m.cols);

  for (const Perturbation& q : s.perturbations) m.perturbations.push_back(tabulate(q, m));
  m.bodies = build_bodies(s.bodies, s.physics, s.grid.spacing);
  std::stable_sort(m.perturbations.begin(), m.perturbations.end(),
                   [](const auto& a, const auto& b) { return a.step < b.step; });
  return m;
}

}  // namespace pond::sim
