#include "tree/jitter_coefficients.h"

#include "tree/pcg32.h"

namespace pond::tree {

float jitter_amplitude(float branch_length, int level) {
  switch (level) {
    case 1: return branch_length * 0.3f;
    case 2: return branch_length * 0.15f;
    case 3: return branch_length * 0.075f;
    default: return 0.0f;
  }
}

void draw_jitter_coefficients(Tree& tree, std::uint64_t seed) {
  Pcg32 rng(seed, RandomStream::jitter);
  for (std::size_t i = 0; i < tree.size(); ++i) {
    TreeVertex& v = tree.vertices[i];
    const std::int32_t p = tree.parents[i];
    if (p == kNoParent) {
      v.jitter = {};
      continue;
    }
    const float len = length(v.position - tree.vertices[static_cast<std::size_t>(p)].position);
    const float s = jitter_amplitude(len, tree.levels[i]);
    const float x = rng.uniform() - 0.5f, y = rng.uniform() - 0.5f, z = rng.uniform() - 0.5f;
    v.jitter = {s * x, s * y, s * z};
  }
}

}  // namespace pond::tree
