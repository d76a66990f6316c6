// Same seed, same tree, bit for bit; another seed, another tree. The golden hashes pin the output
// across platforms and compilers (x86-64, IA-32 SSE, …): PCG32 and IEEE-754 float arithmetic with
// no contraction give the same bits everywhere. On a mismatch the test prints the actual hash.
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdio>
#include <cstring>

#include "tree/noise.h"
#include "tree/tree.h"

namespace pond::tree {
namespace {

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t h = 14695981039346656037ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

std::uint64_t tree_hash(const Tree& t) {
  std::uint64_t h = fnv1a(t.vertices.data(), t.vertices.size() * sizeof(TreeVertex));
  h = fnv1a(t.parents.data(), t.parents.size() * sizeof(std::int32_t), h);
  return fnv1a(t.levels.data(), t.levels.size(), h);
}

std::string hex(std::uint64_t h) {
  char b[17];
  std::snprintf(b, sizeof b, "%016" PRIx64, h);
  return b;
}

TEST(tree_determinism, SameSeedGivesTheSameTreeBitwise) {
  const Tree a = grow_tree({8, 123, 1.0f}), b = grow_tree({8, 123, 1.0f});
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.vertices.data(), b.vertices.data(), a.size() * sizeof(TreeVertex)), 0);
  EXPECT_EQ(a.parents, b.parents);
  EXPECT_EQ(a.levels, b.levels);
}

TEST(tree_determinism, OtherSeedGivesAnotherTree) {
  const Tree a = grow_tree({7, 1, 1.0f}), b = grow_tree({7, 2, 1.0f});
  int same_positions = 0;
  for (std::size_t i = 2; i < a.size(); ++i)
    same_positions += a.vertices[i].position == b.vertices[i].position;
  EXPECT_EQ(same_positions, 0);
  EXPECT_EQ(a.parents, b.parents) << "the topology depends only on the depth";
}

TEST(tree_determinism, GoldenHashes) {
  const std::uint64_t tree7 = tree_hash(grow_tree({7, 1, 1.0f}));
  const std::uint64_t tree8 = tree_hash(grow_tree({8, 42, 1.0f}));
  const NoiseTable noise = make_noise_table(1);
  const std::uint64_t noise1 = fnv1a(noise.values.data(), sizeof noise.values);
  EXPECT_EQ(hex(tree7), "9f35083bf3a70bc4") << "depth 7 seed 1: actual " << hex(tree7);
  EXPECT_EQ(hex(tree8), "2a32c332c1df8f4f") << "depth 8 seed 42: actual " << hex(tree8);
  EXPECT_EQ(hex(noise1), "57193953a8dfb4ac") << "noise seed 1: actual " << hex(noise1);
}

}  // namespace
}  // namespace pond::tree
