#pragma once
// The per-vertex wind vectors of SPEC section 2: how far each vertex moves for unit wind along +x
// (wind_x) and along +z (wind_z).
#include "tree/tree.h"

namespace pond::tree {

// The bending stiffness factor s = |dir| * (0.3 + trunk_level - level): the thinner (higher-level)
// a branch, the more it bends.
float wind_stiffness_factor(float branch_length, int trunk_level, int level);

// A branch's own displacement for unit wind along `axis` (a unit vector in the xz plane):
// normalize(cross(dir, cross(axis, dir))) * s, perpendicular to the branch, in the plane of branch and
// wind, pointing downwind. A branch parallel to the axis (sin of the angle below 1e-6) has no lever
// arm and no defined bending direction: its own displacement is zero (it still moves with its
// parent). Computed in double and rounded once.
Vec3 own_wind_vector(Vec3 dir, Vec3 axis, float s);

// Fills wind_x and wind_z of every vertex from positions, parents, levels and depth: each vertex's
// own vector plus its parent's; the root (the trunk's base) stays fixed. Works for any skeleton whose
// parents precede their children, not only grown ones.
void compute_wind_vectors(Tree& tree);

}  // namespace pond::tree
