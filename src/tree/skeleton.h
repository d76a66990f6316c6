#pragma once
// The fractal skeleton: the article's AddStick recursion (positions, parents, levels only).
#include "tree/tree.h"

namespace pond::tree {

// Fills positions, parents and levels of `tree` (wind vectors and jitter are left zero).
void build_skeleton(const TreeParams& params, Tree& tree);

}  // namespace pond::tree
