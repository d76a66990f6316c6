// The builder's position copies (position_copy.h): the largest |coordinate| they return, over every
// layout, window and lane, against one taken node by node; NaN and infinities are never lost, and
// the blocks' copy refuses them by name but takes coordinates whose sum overflows.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/errors.h"
#include "lod/camera_budget.h"
#include "lod/grid_hierarchy.h"
#include "lod/node_positions.h"
#include "lod/position_copy.h"

namespace pond::lod_test {
namespace {

constexpr int kRows = 13, kCols = 11;  // rows of 11: two four-node groups and a tail of three

// Coordinates of every size (denormals and -0 among them), the grid's three layouts over one data.
struct Layouts {
  std::vector<float> records, x, y, z;
  explicit Layouts(std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> mantissa(-2, 2);
    std::uniform_int_distribution<int> exponent(-140, 20);
    for (int k = 0; k < kRows * kCols; ++k) {
      float v[3];
      for (float& c : v) c = k % 17 == 3 ? -0.0f : std::ldexp(mantissa(rng), exponent(rng));
      x.push_back(v[0]), y.push_back(v[1]), z.push_back(v[2]);
      records.insert(records.end(), {v[0], v[1], v[2], 9e9f, 9e9f, 9e9f});  // velocities: never read
    }
  }
  // Coordinate `c` (0: x, 1: y, 2: z) of node n, in every layout.
  void set(std::size_t n, int c, float v) {
    (c == 0 ? x : c == 1 ? y : z)[n] = v;
    records[6 * n + static_cast<std::size_t>(c)] = v;
  }
  std::vector<std::pair<std::string, lod::NodePositions>> views() const {
    return {{"records", lod::interleaved_positions(records.data(), kRows, kCols)},
            {"arrays", lod::soa_positions(x.data(), y.data(), z.data(), kRows, kCols)},
            {"displacements", lod::grid_displacements(x.data(), y.data(), z.data(), kRows, kCols, 0.5f)}};
  }
};

// For each value of `bads`, coordinate and column from `first_col` on: a pond (seed `seed`) whose
// node (row, column) has that value in that coordinate, each of its views handed to
// check(name, view, node, coordinate, column, value).
template <class Check>
void with_one_bad_node(std::uint32_t seed, int row, int first_col, std::initializer_list<float> bads, Check check) {
  for (float bad : bads)
    for (int coordinate = 0; coordinate < 3; ++coordinate)
      for (int col = first_col; col < kCols; ++col) {
        Layouts data(seed);
        const std::size_t n = static_cast<std::size_t>(row * kCols + col);
        data.set(n, coordinate, bad);
        for (const auto& [name, p] : data.views()) check(name, p, n, coordinate, col, bad);
      }
}

std::uint32_t largest_bits(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z) {
  std::uint32_t largest = 0;
  for (const std::vector<float>* v : {&x, &y, &z})
    for (float c : *v) largest = std::max(largest, std::bit_cast<std::uint32_t>(c) & 0x7fffffffu);
  return largest;
}

TEST(PositionCopy, LargestIsTheLargestMagnitudeCopied) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const Layouts data(seed);
    for (const auto& [name, p] : data.views())
      for (auto [row0, col0, rows, cols] : {std::tuple{0, 0, kRows, kCols}, {2, 1, 5, 9}, {4, 3, 9, 5}, {12, 10, 1, 1}}) {
        std::vector<float> x(static_cast<std::size_t>(rows * cols)), y(x.size()), z(x.size());
        const float largest = lod::copy_window(p, row0, col0, rows, cols, x.data(), y.data(), z.data());
        EXPECT_EQ(std::bit_cast<std::uint32_t>(largest), largest_bits(x, y, z)) << name << " window at " << row0 << "," << col0;
      }
  }
}

// A NaN or an infinity in any coordinate, in a four-node group's every lane or in the tail, comes
// out as a largest that is not finite.
TEST(PositionCopy, NonFiniteCoordinatesAreNeverLost) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  with_one_bad_node(7, 5, 0, {std::numeric_limits<float>::quiet_NaN(), kInf, -kInf},
                    [](const std::string& name, const lod::NodePositions& p, std::size_t, int coordinate, int col, float bad) {
                      std::vector<float> x(static_cast<std::size_t>(kRows * kCols)), y(x.size()), z(x.size());
                      const float largest = lod::copy_positions(p, x.data(), y.data(), z.data());
                      EXPECT_FALSE(std::isfinite(largest)) << name << " coordinate " << coordinate << " col " << col << " " << bad;
                      if (std::isinf(bad)) {
                        EXPECT_EQ(largest, std::numeric_limits<float>::infinity()) << name;
                      }
                    });
}

TEST(PositionCopy, BlocksRefuseNonFiniteCoordinatesByName) {
  with_one_bad_node(9, 6, 1, {std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::infinity()},
                    [](const std::string& name, const lod::NodePositions& p, std::size_t n, int, int col, float) {
                      std::vector<float> x(static_cast<std::size_t>(kRows * kCols)), y(x.size()), z(x.size());
                      const std::string where = "node " + std::to_string(n) + " (row 6, col " + std::to_string(col) + ")";
                      try {
                        lod::copy_finite_block(p, 4, std::min(col - 1, kCols - 5), 5, 5, x.data(), y.data(), z.data());
                        ADD_FAILURE() << name << ": " << where << " not refused";
                      } catch (const InputError& e) {
                        EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << name << ": " << e.what();
                      }
                      // rows 0-4 hold no bad node
                      EXPECT_NO_THROW(lod::copy_finite_block(p, 0, 0, 5, kCols, x.data(), y.data(), z.data())) << name;
                    });
  // Finite coordinates near the largest float: their sum overflows, and they are still taken.
  std::vector<float> big(kRows * kCols, 3e38f);
  std::vector<float> x(static_cast<std::size_t>(kRows * kCols)), y(x.size()), z(x.size());
  EXPECT_NO_THROW(lod::copy_finite_block(lod::soa_positions(big.data(), big.data(), big.data(), kRows, kCols), 0, 0,
                                         kRows, kCols, x.data(), y.data(), z.data()));
  EXPECT_EQ(x[kRows * kCols - 1], 3e38f);
}

// The blocks' AVX2 copy (eight columns at a time, the last eight overlapping) gives the bits of
// the baseline's, in every layout and window at least eight wide, and refuses a non-finite
// coordinate in any lane, the overlapped ones included.
TEST(PositionCopy, TheWideBlockCopyHasTheBaselinesBits) {
  if (!lod::wide_budgets_available()) GTEST_SKIP() << "no AVX2 copy on this CPU or build";
  for (std::uint32_t seed : {4u, 5u}) {
    const Layouts data(seed);
    for (const auto& [name, p] : data.views())
      for (auto [row0, col0, rows, cols] : {std::tuple{0, 0, kRows, kCols}, {2, 1, 5, 9}, {4, 3, 9, 8}, {1, 2, 4, 9}, {12, 0, 1, 11}}) {
        const std::size_t n = static_cast<std::size_t>(rows * cols);
        std::vector<float> x(n), y(n), z(n), wx(n), wy(n), wz(n);
        lod::copy_finite_block(p, row0, col0, rows, cols, x.data(), y.data(), z.data());
        lod::copy_finite_block(p, row0, col0, rows, cols, wx.data(), wy.data(), wz.data(), true);
        for (std::size_t k = 0; k < n; ++k) {
          ASSERT_EQ(std::bit_cast<std::uint32_t>(wx[k]), std::bit_cast<std::uint32_t>(x[k])) << name << " node " << k;
          ASSERT_EQ(std::bit_cast<std::uint32_t>(wy[k]), std::bit_cast<std::uint32_t>(y[k])) << name << " node " << k;
          ASSERT_EQ(std::bit_cast<std::uint32_t>(wz[k]), std::bit_cast<std::uint32_t>(z[k])) << name << " node " << k;
        }
      }
  }
  with_one_bad_node(11, 6, 0, {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()},
                    [](const std::string& name, const lod::NodePositions& p, std::size_t n, int, int col, float) {
                      std::vector<float> x(static_cast<std::size_t>(kRows * kCols)), y(x.size()), z(x.size());
                      const std::string where = "node " + std::to_string(n) + " (row 6, col " + std::to_string(col) + ")";
                      try {
                        lod::copy_finite_block(p, 5, 0, 3, kCols, x.data(), y.data(), z.data(), true);
                        ADD_FAILURE() << name << ": " << where << " not refused";
                      } catch (const InputError& e) {
                        EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << name << ": " << e.what();
                      }
                    });
}

// copy_nodes finds each id's row and column without a division: every node of grids up to the
// largest side (65536), each landing at its own column and row.
TEST(PositionCopy, CopiedNodesLandAtTheirIds) {
  for (auto [rows, cols] : {std::pair{2, 65536}, {65536, 2}, {257, 257}, {1000, 1025}, {3, 40001}}) {
    const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    const std::vector<float> rest(n, 0.0f);  // displacements: a node's world position is (col, 0, row)
    const auto p = lod::grid_displacements(rest.data(), rest.data(), rest.data(), rows, cols, 1.0f);
    std::vector<std::uint32_t> ids(n);
    for (std::size_t k = 0; k < n; ++k) ids[k] = static_cast<std::uint32_t>(k);
    std::vector<float> x(n, -1.0f), y(n, -1.0f), z(n, -1.0f);
    lod::copy_nodes(p, ids, x.data(), y.data(), z.data());
    for (std::size_t k = 0; k < n; ++k) {
      ASSERT_EQ(x[k], static_cast<float>(k % static_cast<std::size_t>(cols))) << rows << "x" << cols << " id " << k;
      ASSERT_EQ(z[k], static_cast<float>(k / static_cast<std::size_t>(cols))) << rows << "x" << cols << " id " << k;
    }
  }
}

}  // namespace
// The builder finds its drawn vertices from their domain ids by a multiply: every node of these
// domains (a 65537-wide one among them) comes back as itself.
TEST(GridHierarchy, DomainIdsGiveTheirNodesBack) {
  for (auto [rows, cols] : {std::pair{2, 65536}, {65536, 2}, {257, 257}, {1000, 1025}, {3, 40001}, {90, 150}}) {
    const lod::GridHierarchy grid(rows, cols);
    for (int y = 0; grid.in_domain({0, y}); ++y)
      for (int x = 0; grid.in_domain({x, y}); ++x)
        ASSERT_EQ(grid.domain_point(grid.domain_id({x, y})), (lod::Point{x, y})) << rows << "x" << cols;
  }
}

}  // namespace pond::lod_test
