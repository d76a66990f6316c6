// NodeRuns against a plain bitmap of the grid: the same nodes, merged runs, covers and minus.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/node_runs.h"

namespace pond::core {
namespace {

constexpr int kRows = 40, kCols = 37;
using Bitmap = std::vector<char>;

Bitmap bitmap_of(std::span<const GridWindow> windows) {
  Bitmap b(kRows * kCols, 0);
  for (const GridWindow& w : windows)
    for (int r = w.row0; r < w.row0 + w.rows; ++r)
      for (int c = w.col0; c < w.col0 + w.cols; ++c) b[r * kCols + c] = 1;
  return b;
}

Bitmap bitmap_of(const NodeRuns& s) {
  Bitmap b(kRows * kCols, 0);
  for (const NodeRun& run : s.runs())
    for (int c = run.col0; c < run.col1; ++c) {
      EXPECT_EQ(b[run.row * kCols + c], 0) << "a node in two runs";
      b[run.row * kCols + c] = 1;
    }
  return b;
}

std::vector<GridWindow> random_windows(std::mt19937& rng, int count) {
  std::vector<GridWindow> out;
  for (int k = 0; k < count; ++k) {
    const int rows = std::uniform_int_distribution(1, 12)(rng), cols = std::uniform_int_distribution(1, 12)(rng);
    out.push_back({std::uniform_int_distribution(0, kRows - rows)(rng), std::uniform_int_distribution(0, kCols - cols)(rng),
                   rows, cols});
  }
  return out;
}

TEST(NodeRuns, HoldsTheWindowsNodesInMergedRuns) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<GridWindow> windows = random_windows(rng, trial % 9);
    const NodeRuns s(windows);
    const Bitmap want = bitmap_of(windows);
    EXPECT_EQ(bitmap_of(s), want);
    std::size_t nodes = 0;
    for (char v : want) nodes += v;
    EXPECT_EQ(s.nodes(), nodes);
    for (std::size_t k = 1; k < s.runs().size(); ++k) {  // ordered, and touching runs merged
      const NodeRun &a = s.runs()[k - 1], &b = s.runs()[k];
      EXPECT_TRUE(a.row < b.row || (a.row == b.row && a.col1 < b.col0));
    }
  }
}

TEST(NodeRuns, CoversExactlyTheWindowsWithinIt) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<GridWindow> windows = random_windows(rng, 1 + trial % 6);
    const NodeRuns s(windows);
    const Bitmap held = bitmap_of(windows);
    for (const GridWindow& w : random_windows(rng, 30)) {
      bool all = true;
      for (int r = w.row0; r < w.row0 + w.rows; ++r)
        for (int c = w.col0; c < w.col0 + w.cols; ++c) all = all && held[r * kCols + c];
      EXPECT_EQ(s.covers(w), all) << w.row0 << " " << w.col0 << " " << w.rows << "x" << w.cols;
    }
    for (const GridWindow& w : windows) EXPECT_TRUE(s.covers(w));
  }
  EXPECT_FALSE(NodeRuns().covers({0, 0, 1, 1}));
  EXPECT_TRUE(NodeRuns().covers({3, 3, 0, 0}));
}

TEST(NodeRuns, MinusAndAddAreSetDifferenceAndUnion) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<GridWindow> wa = random_windows(rng, trial % 7), wb = random_windows(rng, trial % 5);
    const NodeRuns a(wa), b(wb);
    const Bitmap ba = bitmap_of(wa), bb = bitmap_of(wb);
    Bitmap diff(ba.size()), both(ba.size());
    for (std::size_t k = 0; k < ba.size(); ++k) diff[k] = ba[k] && !bb[k], both[k] = ba[k] || bb[k];
    EXPECT_EQ(bitmap_of(a.minus(b)), diff);
    NodeRuns u = a;
    u.add(b);
    EXPECT_EQ(bitmap_of(u), both);
  }
}

}  // namespace
}  // namespace pond::core
