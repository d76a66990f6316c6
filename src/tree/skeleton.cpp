#include "tree/skeleton.h"

#include "tree/pcg32.h"

namespace pond::tree {
namespace {

// The article's constants: each level is 0.7 as long as the one carrying it, the children spread
// sideways by 0.6 of that length, and the three sit 120 degrees apart around their parent
// (0.866 = sin 120°, 0.5 = -cos 120°).
constexpr float kLengthRatio = 0.7f;
constexpr float kSpreadRatio = 0.6f;
constexpr float kSin120 = 0.866f;

class SkeletonBuilder {
 public:
  SkeletonBuilder(const TreeParams& params, Tree& tree)
      : tree_(tree), rng_(params.seed, RandomStream::skeleton) {}

  // AddStick(level, parent, dir). The article keeps the running length in a global, multiplies it
  // by 0.7 before recursing and divides it back afterwards; passing it down as an argument is the
  // same thing with an exact restore (x * 0.7 / 0.7 need not be x in floating point).
  void add_stick(int level, std::int32_t parent, Vec3 dir, float len) {
    const auto self = static_cast<std::int32_t>(tree_.vertices.size());
    TreeVertex v;
    v.position = tree_.vertices[static_cast<std::size_t>(parent)].position + dir;
    tree_.vertices.push_back(v);
    tree_.parents.push_back(parent);
    tree_.levels.push_back(static_cast<std::int8_t>(level));
    if (level == 1) return;

    len = len * kLengthRatio;
    const Vec3 d = normalize(dir) * len;
    const float s = len * kSpreadRatio;
    const Vec3 vS = normalize(cross(dir, random_side(dir))) * s;
    const Vec3 vC = normalize(cross(dir, vS)) * s;
    // Each child draws its own r in [0, 1) just before it is grown, as the article's argument
    // evaluation does: the draws interleave with the grandchildren's.
    add_stick(level - 1, self, vS * 0.5f + vC * kSin120 + d * (rng_.uniform() + 1.5f) * 0.5f, len);
    add_stick(level - 1, self, vS * -1.0f + d * (rng_.uniform() + 1.5f) * 0.5f, len);
    add_stick(level - 1, self, vS * 0.5f + vC * -kSin120 + d * (rng_.uniform() + 1.5f) * 0.5f, len);
  }

 private:
  // The article's random vector (Rnd, Rnd, Rnd), which picks the side the children spread to. One
  // (nearly) parallel to `dir` would leave the cross product without a direction, so it is drawn
  // again: a deterministic redraw, with probability about 1e-7 per branch.
  Vec3 random_side(Vec3 dir) {
    for (;;) {
      const float x = rng_.uniform(), y = rng_.uniform(), z = rng_.uniform();
      const Vec3 r{x, y, z};
      const Vec3 c = cross(dir, r);
      if (dot(c, c) > 1e-6f * dot(dir, dir) * dot(r, r)) return r;
    }
  }

  Tree& tree_;
  Pcg32 rng_;
};

}  // namespace

void build_skeleton(const TreeParams& params, Tree& tree) {
  const std::size_t n = tree_vertex_count(params.depth);
  tree.depth = params.depth;
  tree.vertices.clear();
  tree.parents.clear();
  tree.levels.clear();
  tree.vertices.reserve(n);
  tree.parents.reserve(n);
  tree.levels.reserve(n);

  tree.vertices.push_back(TreeVertex{});  // the trunk's base, at the origin
  tree.parents.push_back(kNoParent);
  tree.levels.push_back(kRootLevel);
  // The running length starts as the trunk's own, so the first branches are 0.7 of the trunk along
  // it (times (r + 1.5) / 2) and spread 0.42 of it sideways: 26 to 39 degrees off their parent.
  SkeletonBuilder(params, tree).add_stick(params.depth, 0, Vec3{0.0f, params.trunk_length, 0.0f},
                                          params.trunk_length);
}

}  // namespace pond::tree
