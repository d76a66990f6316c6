// Each wide backend's kernel (sse, avx2, avx512, neon: those this build has and this CPU runs),
// called directly, gives the scalar kernel's bits at every row width from 1 to 2 * lanes + 1:
// rows narrower than a vector (the scalar or half-width tail), one vector, a vector and a partial
// one (the last chunk overlapping the one before), two vectors and one column more. Random
// displacements and velocities, signed zeros among them, and every node kind; with and without
// the reach and the tile bounds, exact and fast math, one to three rows (one row has no springs
// to a next row).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "shared/exact_math.h"
#include "sim/aligned_buffer.h"
#include "sim/backends.h"
#include "sim/step_view.h"
#include "sim/tile_bounds.h"
#include "test_util.h"

namespace pond::sim {
namespace {

int lanes(Backend b) {
  switch (b) {
    case Backend::sse: return 4;
    case Backend::avx2: return 8;
    case Backend::avx512: return 16;
    case Backend::neon: return 4;
    default: return 1;
  }
}

// One substep's inputs: SoA arrays of a rows x cols grid.
struct Grid {
  int rows, cols;
  std::vector<float> u[3], v[3];
  std::vector<std::uint8_t> kinds;
};

Grid random_grid(int rows, int cols, std::mt19937& rng) {
  Grid g{rows, cols, {}, {}, {}};
  const std::size_t n = static_cast<std::size_t>(rows) * cols;
  std::uniform_real_distribution<float> value(-0.4f, 0.4f);
  std::uniform_int_distribution<int> pick(0, 9);
  const auto sample = [&] {
    const int k = pick(rng);
    return k == 0 ? 0.0f : k == 1 ? -0.0f : value(rng);  // a node at rest keeps signed zeros
  };
  for (int axis = 0; axis < 3; ++axis) {
    g.u[axis].resize(n), g.v[axis].resize(n);
    for (std::size_t i = 0; i < n; ++i) g.u[axis][i] = sample(), g.v[axis][i] = sample();
  }
  g.kinds.resize(n);
  for (auto& k : g.kinds) k = static_cast<std::uint8_t>(pick(rng) < 6 ? 0 : pick(rng) < 5 ? 1 : 2);
  return g;
}

// The outputs of one kernel call on g.
struct Result {
  std::vector<float> out[6];
  float check = 0, reach = 0;
  std::vector<shared::TileBounds> tiles;
};

Result step(Backend b, const Grid& g, int rsqrt_steps, bool reach, bool tiles) {
  const StepRowsFn kernel = step_rows_for(b, rsqrt_steps, reach, tiles);
  const std::size_t n = static_cast<std::size_t>(g.rows) * g.cols;
  Result r;
  for (auto& o : r.out) o.assign(n, std::nanf(""));
  StepConstants k;
  k.kc = 7.0f * 0.4f / 4.0f, k.kd = 0.05f * 0.4f / 4.0f, k.dt = 0.4f, k.rest_edge = 1.0f;
  k.rest_diag = 1.41421354f, k.rsqrt_steps = rsqrt_steps;
  const StepView view{g.u[0].data(),   g.u[1].data(),   g.u[2].data(),   g.v[0].data(),   g.v[1].data(),
                      g.v[2].data(),   r.out[0].data(), r.out[1].data(), r.out[2].data(), r.out[3].data(),
                      r.out[4].data(), r.out[5].data(), g.kinds.data(),  g.rows,          g.cols,
                      k};
  AlignedBuffer<float> scratch(std::size_t{kSpringRows} * kSlots);
  AlignedBuffer<float> columns(std::size_t{6} * kColumnsPitch);
  const TileGrid grid(g.rows, g.cols);
  r.tiles.resize(grid.tiles());
  TileSink sink{r.tiles.data(), columns.data(), 0};
  r.check = kernel(view, 0, g.rows, scratch.data(), &r.reach, tiles ? &sink : nullptr);
  return r;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b, std::string& where) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::bit_cast<std::uint32_t>(a[i]) != std::bit_cast<std::uint32_t>(b[i])) {
      where = "node " + std::to_string(i) + ": " + std::to_string(a[i]) + " vs " + std::to_string(b[i]);
      return false;
    }
  return true;
}

TEST(KernelWidths, EveryWideBackendGivesTheScalarBitsAtEveryTailWidth) {
  std::mt19937 rng(59);
  int wide_backends = 0;
  for (Backend b : test::available_backends()) {
    if (b == Backend::scalar) continue;
    ++wide_backends;
    for (int cols = 1; cols <= 2 * lanes(b) + 1; ++cols)
      for (int rows : {1, 2, 3}) {
        const Grid g = random_grid(rows, cols, rng);
        for (int steps : {shared::kRsqrtStepsExact, shared::kRsqrtStepsFast})
          for (bool reach : {false, true})
            for (bool tiles : {false, true}) {
              const std::string what = std::string(backend_name(b)) + " " + std::to_string(rows) + "x" +
                                       std::to_string(cols) + " steps " + std::to_string(steps) +
                                       (reach ? " reach" : "") + (tiles ? " tiles" : "");
              const Result want = step(Backend::scalar, g, steps, reach, tiles);
              const Result got = step(b, g, steps, reach, tiles);
              for (int a = 0; a < 6; ++a) {
                std::string where;
                EXPECT_TRUE(same_bits(got.out[a], want.out[a], where)) << what << ", output " << a << ", " << where;
              }
              EXPECT_EQ(std::isfinite(got.check), std::isfinite(want.check)) << what;
              if (reach) {
                EXPECT_EQ(got.reach, want.reach) << what;
              }
              for (std::size_t t = 0; tiles && t < want.tiles.size(); ++t) {
                const auto& x = got.tiles[t];
                const auto& y = want.tiles[t];
                EXPECT_TRUE(x.min_x == y.min_x && x.min_y == y.min_y && x.min_z == y.min_z && x.max_x == y.max_x &&
                            x.max_y == y.max_y && x.max_z == y.max_z)
                    << what << ", tile " << t;
              }
            }
      }
  }
  std::printf("wide backends checked: %d\n", wide_backends);
  EXPECT_GT(wide_backends, 0) << "no wide backend in this build runs on this CPU";
}

}  // namespace
}  // namespace pond::sim
