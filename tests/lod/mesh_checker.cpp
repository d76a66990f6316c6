#include "lod/mesh_checker.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace pond::lod_test {
namespace {

struct Node {
  long long col, row;
};

Node node_of(std::uint32_t n, int cols) { return {n % cols, n / cols}; }

bool on_same_border_line(Node a, Node b, int rows, int cols) {
  return (a.row == b.row && (a.row == 0 || a.row == rows - 1)) ||
         (a.col == b.col && (a.col == 0 || a.col == cols - 1));
}

}  // namespace

std::string topology_problem(const std::vector<std::uint32_t>& tris, int rows, int cols) {
  if (tris.size() % 3) return "index count is not a multiple of 3";
  const std::uint64_t nodes = static_cast<std::uint64_t>(rows) * cols;
  std::unordered_map<std::uint64_t, int> directed;
  long long twice_area = 0;
  for (std::size_t t = 0; t < tris.size(); t += 3) {
    for (int k = 0; k < 3; ++k)
      if (tris[t + k] >= nodes) return "triangle " + std::to_string(t / 3) + " has index out of range";
    const Node a = node_of(tris[t], cols), b = node_of(tris[t + 1], cols), c = node_of(tris[t + 2], cols);
    // Rest positions (col, 0, row): normal_y of (b - a) x (c - a) is dz_ab * dx_ac - dx_ab * dz_ac.
    const long long normal_y = (b.row - a.row) * (c.col - a.col) - (b.col - a.col) * (c.row - a.row);
    if (normal_y <= 0)
      return "triangle " + std::to_string(t / 3) + " has rest normal y " + std::to_string(normal_y);
    twice_area += normal_y;
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t key = static_cast<std::uint64_t>(tris[t + k]) * nodes + tris[t + (k + 1) % 3];
      if (++directed[key] > 1) return "a directed edge is used twice (overlap or flipped triangle)";
    }
  }
  for (const auto& [key, count] : directed) {
    const std::uint32_t from = static_cast<std::uint32_t>(key / nodes), to = static_cast<std::uint32_t>(key % nodes);
    if (directed.count(static_cast<std::uint64_t>(to) * nodes + from)) continue;
    if (!on_same_border_line(node_of(from, cols), node_of(to, cols), rows, cols))
      return "edge " + std::to_string(from) + "-" + std::to_string(to) +
             " is used once but is not on the grid border (crack or T-junction)";
  }
  const long long expected = 2ll * (rows - 1) * (cols - 1);
  if (twice_area != expected)
    return "parametric area " + std::to_string(static_cast<double>(twice_area) / 2) + " != " + std::to_string(expected / 2);
  return "";
}

ErrorReport screen_errors(const std::vector<std::uint32_t>& tris, int rows, int cols,
                          const std::vector<float>& state, const CheckCamera& cam) {
  const std::size_t nodes = static_cast<std::size_t>(rows) * cols;
  std::vector<double> error(nodes, -1);  // world distance; -1 = not covered
  std::vector<char> vertex(nodes, 0);
  auto pos = [&](std::size_t n, int k) { return static_cast<double>(state[n * 6 + k]); };
  for (std::uint32_t v : tris) vertex[v] = 1;
  for (std::size_t t = 0; t < tris.size(); t += 3) {
    const Node a = node_of(tris[t], cols), b = node_of(tris[t + 1], cols), c = node_of(tris[t + 2], cols);
    const long long det = (b.col - a.col) * (c.row - a.row) - (b.row - a.row) * (c.col - a.col);
    if (det == 0) continue;
    for (long long r = std::min({a.row, b.row, c.row}); r <= std::max({a.row, b.row, c.row}); ++r)
      for (long long q = std::min({a.col, b.col, c.col}); q <= std::max({a.col, b.col, c.col}); ++q) {
        // Barycentric weights in index space, exact integers over det.
        const long long wb = (q - a.col) * (c.row - a.row) - (r - a.row) * (c.col - a.col);
        const long long wc = (b.col - a.col) * (r - a.row) - (b.row - a.row) * (q - a.col);
        const long long wa = det - wb - wc;
        const double fa = static_cast<double>(wa), fb = static_cast<double>(wb), fc = static_cast<double>(wc);
        const bool inside = det > 0 ? (wa >= 0 && wb >= 0 && wc >= 0) : (wa <= 0 && wb <= 0 && wc <= 0);
        if (!inside) continue;
        const std::size_t n = static_cast<std::size_t>(r) * cols + static_cast<std::size_t>(q);
        double d2 = 0;
        for (int k = 0; k < 3; ++k) {
          const double interp = (fa * pos(tris[t], k) + fb * pos(tris[t + 1], k) + fc * pos(tris[t + 2], k)) /
                                static_cast<double>(det);
          d2 += (pos(n, k) - interp) * (pos(n, k) - interp);
        }
        error[n] = std::max(error[n], std::sqrt(d2));
      }
  }
  // The camera, from the contract: up is world +y, depth along the view direction.
  const double fx = cam.target[0] - cam.eye[0], fy = cam.target[1] - cam.eye[1], fz = cam.target[2] - cam.eye[2];
  const double fl = std::sqrt(fx * fx + fy * fy + fz * fz);
  const double f[3] = {fx / fl, fy / fl, fz / fl};
  double r[3] = {-f[2], 0, f[0]};  // f x (0, 1, 0)
  const double rl = std::sqrt(r[0] * r[0] + r[2] * r[2]);
  if (rl < 1e-9) r[0] = 1, r[2] = 0; else r[0] /= rl, r[2] /= rl;
  const double u[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
  const double tan_y = std::tan(cam.fovy_degrees * std::numbers::pi / 360);
  const double tan_x = tan_y * cam.width / cam.height;
  const double pixels = cam.height / (2 * tan_y);

  ErrorReport rep;
  for (std::size_t n = 0; n < nodes; ++n) {
    if (vertex[n]) continue;
    ++rep.left_out;
    if (error[n] < 0) {
      ++rep.uncovered;
      continue;
    }
    const double d[3] = {pos(n, 0) - cam.eye[0], pos(n, 1) - cam.eye[1], pos(n, 2) - cam.eye[2]};
    const double depth = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    const double sx = d[0] * r[0] + d[1] * r[1] + d[2] * r[2], sy = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
    if (!(depth > 0) || std::abs(sx) > tan_x * depth || std::abs(sy) > tan_y * depth) continue;
    ++rep.left_out_in_view;
    rep.max_error_px = std::max(rep.max_error_px, error[n] / depth * pixels);
  }
  return rep;
}

}  // namespace pond::lod_test
