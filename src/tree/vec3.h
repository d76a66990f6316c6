#pragma once
// The tree's 3-vector: the very type of the shared GPU header (shaders/shared/tree_wind.h), so the
// skeleton, the wind vectors and the CPU bend evaluation hand vertices to the shared formula without
// conversion. The helpers below are the few the generator needs beyond that header's + - *.
#include <cmath>

#include "shared/tree_wind.h"

namespace pond::tree {

using Vec3 = shared::tree_wind::vec3;  // its + - * and == are found by argument-dependent lookup

inline float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(Vec3 a) { return std::sqrt(dot(a, a)); }
// Divides by the length (correctly rounded, so the same bits on every IEEE platform); the caller
// makes sure `a` is not zero.
inline Vec3 normalize(Vec3 a) {
  const float l = length(a);
  return {a.x / l, a.y / l, a.z / l};
}

}  // namespace pond::tree
