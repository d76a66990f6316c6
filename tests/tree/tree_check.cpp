// Checks a `pond tree` output against SPEC.md §2 (written from the spec, not from src/tree), for
// the command-line test:
//   tree_check PREFIX DEPTH [OTHER_PREFIX]
// PREFIX.vertices.npy (V, 12: position, wind X, wind Z, jitter) and PREFIX.parents.npy (V) must be
// the spec's tree of DEPTH: V = 1 + (3^DEPTH - 1) / 2; the root at the origin with no parent and no
// wind; each vertex after its parent, a trunk straight up; each branch's wind vectors its parent's
// plus its own, perpendicular to the branch, in the plane of branch and axis, of length
// |dir| (0.3 + trunk level - level); each of a vertex's three children 0.75 to 1.25 of the running
// length L along the parent's branch and 0.6 L across it, the three across parts 120 degrees
// apart (summing to zero), L shrinking by 0.7 a level; jitter zero on all but the three thinnest
// levels and within |dir| {0.3, 0.15, 0.075} / 2 there, and not all zero. With OTHER_PREFIX (another
// seed): the same trunk, and most other vertices elsewhere. Prints one line and exits 0; 1 naming
// the first broken rule; 2 when a file cannot be read.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/plain_npy.h"

namespace {

using V3 = std::array<double, 3>;
V3 sub(V3 a, V3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 add(V3 a, V3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V3 mul(V3 a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(V3 a, V3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double len(V3 a) { return std::sqrt(dot(a, a)); }
V3 cross(V3 a, V3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

struct Tree {
  std::vector<std::array<V3, 4>> v;  // position, wind X, wind Z, jitter
  std::vector<std::int32_t> parent;
};

Tree load(const std::string& prefix) {
  const auto vertices = pond::test::read_plain_npy<float>(prefix + ".vertices.npy", "<f4");
  const auto parents = pond::test::read_plain_npy<std::int32_t>(prefix + ".parents.npy", "<i4");
  if (vertices.shape.size() != 2 || vertices.shape[1] != 12 || parents.shape.size() != 1 ||
      parents.shape[0] != vertices.shape[0]) {
    std::fprintf(stderr, "tree_check: %s: shapes are not (V, 12) and (V)\n", prefix.c_str());
    std::exit(2);
  }
  Tree t;
  for (std::size_t k = 0; k < parents.shape[0]; ++k) {
    std::array<V3, 4> row;
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 3; ++c) row[a][c] = vertices.data[k * 12 + a * 3 + c];
    t.v.push_back(row);
  }
  t.parent = parents.data;
  return t;
}

int failures = 0;
void fail(const std::string& what) {
  if (failures++ < 10) std::printf("tree_check: %s\n", what.c_str());
}
bool near(double a, double b, double tol) { return std::fabs(a - b) <= tol; }

// The spec's own wind vector of a branch `dir` for a unit `axis`: perpendicular to the branch in
// their plane, length s; zero for a branch along the axis.
V3 own_wind(V3 dir, V3 axis, double s) {
  const V3 v = cross(dir, cross(axis, dir));
  const double l = len(v);
  return l < 1e-6 * dot(dir, dir) ? V3{0, 0, 0} : mul(v, s / l);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: tree_check PREFIX DEPTH [OTHER_PREFIX]\n");
    return 2;
  }
  const Tree t = load(argv[1]);
  const int depth = std::atoi(argv[2]);
  std::size_t want = 1;
  for (int k = 0, p = 1; k < depth; ++k, p *= 3) want += static_cast<std::size_t>(p);
  if (t.v.size() != want) fail("expected " + std::to_string(want) + " vertices, found " + std::to_string(t.v.size()));
  const std::size_t n = t.v.size();
  if (n < 2) return 1;
  // Depth below the root and the level of each vertex (the trunk's is `depth`, the thinnest 1).
  std::vector<int> below(n, 0);
  if (t.parent[0] != -1 || len(t.v[0][0]) != 0 || len(t.v[0][1]) != 0 || len(t.v[0][2]) != 0)
    fail("the root is not a parentless vertex at the origin without wind");
  for (std::size_t k = 1; k < n; ++k) {
    if (t.parent[k] < 0 || static_cast<std::size_t>(t.parent[k]) >= k) {
      fail("vertex " + std::to_string(k) + " has parent " + std::to_string(t.parent[k]));
      return 1;
    }
    below[k] = below[static_cast<std::size_t>(t.parent[k])] + 1;
  }
  const V3 trunk = sub(t.v[1][0], t.v[0][0]);
  if (!(trunk[1] > 0) || std::hypot(trunk[0], trunk[2]) > 1e-6 * trunk[1]) fail("the trunk is not straight up");
  const double trunk_length = len(trunk);
  std::vector<std::vector<std::size_t>> children(n);
  double largest_jitter = 0;
  for (std::size_t k = 1; k < n; ++k) {
    const std::size_t p = static_cast<std::size_t>(t.parent[k]);
    children[p].push_back(k);
    const int level = depth - below[k] + 1;
    if (level < 1) fail("vertex " + std::to_string(k) + " lies deeper than the depth");
    const V3 dir = sub(t.v[k][0], t.v[p][0]);
    const double s = len(dir) * (0.3 + depth - level), tol = 1e-5 * (1 + len(t.v[k][1]) + len(t.v[k][2]));
    const V3 wx = add(t.v[p][1], own_wind(dir, {1, 0, 0}, s)), wz = add(t.v[p][2], own_wind(dir, {0, 0, 1}, s));
    if (len(sub(wx, t.v[k][1])) > tol || len(sub(wz, t.v[k][2])) > tol)
      fail("vertex " + std::to_string(k) + " (level " + std::to_string(level) + "): wind vectors differ from the " +
           "parent's plus the branch's own");
    const double factor = level == 1 ? 0.3 : level == 2 ? 0.15 : level == 3 ? 0.075 : 0.0;
    for (int c = 0; c < 3; ++c) {
      const double j = std::fabs(t.v[k][3][c]), most = 0.5 * factor * len(dir);
      if (j > most * (1 + 1e-5)) fail("vertex " + std::to_string(k) + ": jitter " + std::to_string(j) + " beyond " + std::to_string(most));
      if (most > 0) largest_jitter = std::max(largest_jitter, j / most);
    }
  }
  if (depth >= 1 && !(largest_jitter > 0.5)) fail("the jitter coefficients are (nearly) all zero");
  // The branching: children of vertex k (k below the root) along and across k's own branch.
  for (std::size_t k = 1; k < n; ++k) {
    if (children[k].empty()) continue;
    if (children[k].size() != 3) {
      fail("vertex " + std::to_string(k) + " has " + std::to_string(children[k].size()) + " children");
      continue;
    }
    const V3 along = mul(sub(t.v[k][0], t.v[static_cast<std::size_t>(t.parent[k])][0]), 1.0);
    const V3 unit = mul(along, 1 / len(along));
    const double L = trunk_length * std::pow(0.7, below[k]);
    V3 across_sum{0, 0, 0};
    for (std::size_t c : children[k]) {
      const V3 dir = sub(t.v[c][0], t.v[k][0]);
      const double a = dot(dir, unit);
      const V3 across = sub(dir, mul(unit, a));
      across_sum = add(across_sum, across);
      if (a < 0.75 * L * (1 - 1e-4) || a > 1.25 * L * (1 + 1e-4))
        fail("vertex " + std::to_string(c) + ": " + std::to_string(a / L) + " L along its parent's branch, not 0.75 to 1.25");
      if (!near(len(across), 0.6 * L, 1e-3 * L))
        fail("vertex " + std::to_string(c) + ": " + std::to_string(len(across) / L) + " L across its parent's branch, not 0.6");
    }
    if (len(across_sum) > 2e-3 * L) fail("the children of vertex " + std::to_string(k) + " are not 120 degrees apart");
  }
  std::size_t moved = 0;
  if (argc == 4) {
    const Tree o = load(argv[3]);
    if (o.v.size() != n) {
      fail("the other seed's tree has another size");
    } else {
      if (len(sub(o.v[1][0], t.v[1][0])) != 0) fail("the other seed's trunk differs");
      for (std::size_t k = 2; k < n; ++k) moved += len(sub(o.v[k][0], t.v[k][0])) > 1e-3 * trunk_length;
      if (moved < (n - 2) * 9 / 10)
        fail("the other seed moved only " + std::to_string(moved) + " of " + std::to_string(n - 2) + " branch tips");
    }
  }
  if (failures) return 1;
  std::printf("tree_check: %zu vertices of depth %d follow the spec (trunk %.3f, largest jitter %.2f of its bound)%s\n",
              n, depth, trunk_length, largest_jitter,
              argc == 4 ? (", the other seed moved " + std::to_string(moved) + " tips").c_str() : "");
  return 0;
}
