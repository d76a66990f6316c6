#pragma once
// The twig-jitter coefficients of SPEC section 2: three random numbers per vertex on the three
// thinnest levels, larger for thinner twigs, so that each twig answers the shared noise q with its
// own mix and the twigs flutter out of step.
#include <cstdint>

#include "tree/tree.h"

namespace pond::tree {

// The amplitude factor per level: |dir| * {0.3, 0.15, 0.075} for levels 1, 2, 3, and 0 above.
float jitter_amplitude(float branch_length, int level);

// Fills jitter of every vertex: amplitude * (rand - 0.5) per component. Three numbers are drawn for
// every stick, in vertex order, whatever its level (as the article does), from the seed's jitter
// stream; the root gets zero.
void draw_jitter_coefficients(Tree& tree, std::uint64_t seed);

}  // namespace pond::tree
