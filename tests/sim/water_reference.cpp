#include "sim/water_reference.h"

#include <cmath>
#include <cstdio>

namespace pond::reference {
namespace {

const char* kind_name(Kind k) { return k == Kind::fixed ? "fixed" : k == Kind::vertical ? "vertical" : "free"; }

}  // namespace

std::string scene_json(const Pond& p) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                R"({"grid": {"rows": %d, "cols": %d, "spacing": %.17g}, )"
                R"("physics": {"mass": %.17g, "stiffness": %.17g, "damping": %.17g, "dt": %.17g, "substeps": %d, "rest_ratio": %.17g}, )"
                R"("border": "%s", "constraints": [)",
                p.rows, p.cols, p.spacing, p.mass, p.stiffness, p.damping, p.dt, p.substeps, p.rest_ratio,
                kind_name(p.border));
  std::string json = buf;
  for (std::size_t k = 0; k < p.constraints.size(); ++k) {
    const Rect& r = p.constraints[k];
    std::snprintf(buf, sizeof buf, R"(%s{"kind": "%s", "rows": [%d, %d], "cols": [%d, %d]})", k ? ", " : "",
                  kind_name(r.kind), r.row0, r.row1, r.col0, r.col1);
    json += buf;
  }
  json += R"(], "perturbations": [)";
  for (std::size_t k = 0; k < p.splashes.size(); ++k) {
    const Splash& s = p.splashes[k];
    std::snprintf(buf, sizeof buf,
                  R"(%s{"step": %lld, "row": %.17g, "col": %.17g, "radius": %.17g, "amplitude": %.17g, )"
                  R"("target": "%s", "mode": "%s"})",
                  k ? ", " : "", static_cast<long long>(s.step), s.row, s.col, s.radius, s.amplitude,
                  s.position ? "position" : "velocity", s.set ? "set" : "add");
    json += buf;
  }
  return json + "]}";
}

Water::Water(const Pond& pond) : pond_(pond) {
  const int R = pond.rows, C = pond.cols;
  kinds_.assign(static_cast<std::size_t>(R) * C, Kind::free);
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j)
      if (i == 0 || j == 0 || i == R - 1 || j == C - 1) kinds_[static_cast<std::size_t>(i) * C + j] = pond.border;
  // Fixed wins over vertical, whatever the order of the rectangles.
  for (const Kind k : {Kind::vertical, Kind::fixed})
    for (const Rect& r : pond.constraints)
      if (r.kind == k)
        for (int i = r.row0; i <= r.row1; ++i)
          for (int j = r.col0; j <= r.col1; ++j) {
            Kind& at = kinds_[static_cast<std::size_t>(i) * C + j];
            if (at != Kind::fixed) at = k;
          }
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) nodes_.push_back({j * pond.spacing, 0, i * pond.spacing, 0, 0, 0});
}

void Water::perturb(const Splash& s) {
  const double h = pond_.spacing;
  for (int i = 0; i < pond_.rows; ++i)
    for (int j = 0; j < pond_.cols; ++j) {
      if (kind(i, j) == Kind::fixed) continue;
      const double di = (i - s.row) * h, dj = (j - s.col) * h, d2 = di * di + dj * dj;
      if (std::sqrt(d2) > 3 * s.radius) continue;
      const double w = s.amplitude * std::exp(-d2 / (2 * s.radius * s.radius));
      Node& n = nodes_[static_cast<std::size_t>(i) * pond_.cols + j];
      double& v = s.position ? n.y : n.vy;
      v = s.set ? w : v + w;
    }
}

void Water::substep(double dt) {
  const int R = pond_.rows, C = pond_.cols;
  const double h = pond_.spacing, c = pond_.stiffness;
  std::vector<std::array<double, 3>> force(nodes_.size(), {0, 0, 0});
  // Each spring once, from node a to a neighbour b after it: right, down, and both diagonals.
  const int offsets[4][2] = {{0, 1}, {1, 0}, {1, 1}, {1, -1}};
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j)
      for (const auto& o : offsets) {
        const int bi = i + o[0], bj = j + o[1];
        if (bi >= R || bj < 0 || bj >= C) continue;
        const bool diagonal = o[0] != 0 && o[1] != 0;
        const double rest = pond_.rest_ratio * h * (diagonal ? std::sqrt(2.0) : 1.0);
        const std::size_t a = static_cast<std::size_t>(i) * C + j, b = static_cast<std::size_t>(bi) * C + bj;
        const double d[3] = {nodes_[b].x - nodes_[a].x, nodes_[b].y - nodes_[a].y, nodes_[b].z - nodes_[a].z};
        const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int k = 0; k < 3; ++k) {
          const double f = c * d[k] * (1 - rest / l);  // on a, toward b when stretched
          force[a][k] += f;
          force[b][k] -= f;
        }
      }
  const double m = pond_.mass, gamma = pond_.damping;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    Node& p = nodes_[n];
    const Kind k = kinds_[n];
    p.vx += (force[n][0] - gamma * p.vx) / m * dt;
    p.vy += (force[n][1] - gamma * p.vy) / m * dt;
    p.vz += (force[n][2] - gamma * p.vz) / m * dt;
    if (k != Kind::free) p.vx = p.vz = 0;
    if (k == Kind::fixed) p.vy = 0;
    p.x += p.vx * dt;
    p.y += p.vy * dt;
    p.z += p.vz * dt;
  }
}

void Water::step() {
  for (const Splash& s : pond_.splashes)
    if (s.step == steps_) perturb(s);
  for (int k = 0; k < pond_.substeps; ++k) substep(pond_.dt / pond_.substeps);
  ++steps_;
}

std::array<double, 3> normal(const std::vector<std::array<double, 3>>& x, int rows, int cols, int i, int j) {
  auto at = [&](int r, int c) { return x[static_cast<std::size_t>(r) * cols + c]; };
  const int i1 = i + 1 < rows ? i + 1 : i, i0 = i > 0 ? i - 1 : i;
  const int j1 = j + 1 < cols ? j + 1 : j, j0 = j > 0 ? j - 1 : j;
  const auto up = at(i1, j), down = at(i0, j), right = at(i, j1), left = at(i, j0);
  const double a[3] = {up[0] - down[0], up[1] - down[1], up[2] - down[2]};
  const double b[3] = {right[0] - left[0], right[1] - left[1], right[2] - left[2]};
  const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return {n[0] / l, n[1] / l, n[2] / l};
}

}  // namespace pond::reference
