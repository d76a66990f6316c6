// The builder where only parts of the positions are on the host (NodePositions::fetch), as with a
// discrete GPU's state read back in windows: the same mesh and the same drawn positions as with
// every node at hand, reading only the nodes it needs. Nodes the host lacks are NaN here, so a read
// of one fails the build or the comparison.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/node_runs.h"
#include "lod/lod_builder.h"
#include "lod/mesh_checker.h"
#include "lod/rippled_states.h"
#include "lod/tile_ranges.h"

namespace pond::lod_test {
namespace {

// A state (STATE.npy layout) of which the host holds some nodes; the rest read NaN.
class PartialHost : public lod::NodeFetch {
 public:
  PartialHost(const std::vector<float>& truth, int rows, int cols)
      : truth_(truth), host_(truth.size(), std::numeric_limits<float>::quiet_NaN()), rows_(rows), cols_(cols) {}

  bool holds(const core::GridWindow& w) override { return held_.covers(w); }
  void bring_and_wait(std::span<const core::GridWindow> windows) override {
    ++rounds;
    corners_alone += std::all_of(windows.begin(), windows.end(), [](const core::GridWindow& w) { return w.rows * w.cols == 1; });
    const core::NodeRuns want = core::NodeRuns(windows).minus(held_);
    for (const core::NodeRun& r : want.runs())
      for (int c = r.col0; c < r.col1; ++c)
        for (int k = 0; k < 6; ++k) {
          const std::size_t at = 6 * (static_cast<std::size_t>(r.row) * cols_ + c) + k;
          host_[at] = truth_[at];
        }
    held_.add(want);
  }
  // A new frame: the host holds `windows` (all: nullopt) and nothing else.
  void start_frame(const std::optional<std::vector<core::GridWindow>>& windows) {
    held_ = {}, rounds = 0, corners_alone = 0;
    host_.assign(truth_.size(), std::numeric_limits<float>::quiet_NaN());
    const core::GridWindow all{0, 0, rows_, cols_};
    if (windows) bring_and_wait(*windows);
    else bring_and_wait(std::span(&all, 1));
    rounds = 0, corners_alone = 0;
  }
  std::size_t held_nodes() const { return held_.nodes(); }
  lod::NodePositions positions() {
    lod::NodePositions p = lod::interleaved_positions(host_.data(), rows_, cols_);
    p.fetch = this;
    return p;
  }
  int rounds = 0;
  int corners_alone = 0;  // rounds that brought single nodes only (leaves' corners)

 private:
  const std::vector<float>& truth_;
  std::vector<float> host_;
  core::NodeRuns held_;
  int rows_, cols_;
};

lod::Camera camera_of(const CheckCamera& c) { return {c.eye, c.target, c.fovy_degrees, c.width, c.height}; }

struct Frame {
  const std::vector<float>* state;
  CheckCamera camera;
};

// Builds `frames` in turn with every node at hand and with a partial host that keeps what the
// last build read (the first frame: nothing): the same triangles and drawn positions each time.
// Returns the most nodes the partial host held after a frame; counts the rounds of bringing after
// the first frame into `rounds` and those that brought leaves' corners alone into `corners_alone`.
struct Rounds {
  int rounds = 0, corners_alone = 0;
};
Rounds compare_builds(int rows, int cols, const std::vector<Frame>& frames, const std::string& what,
                      std::size_t* most_held = nullptr) {
  lod::LodBuilder full(rows, cols), partial(rows, cols);
  std::vector<std::uint32_t> a(full.max_indices()), b(partial.max_indices());
  std::optional<std::vector<core::GridWindow>> kept = std::vector<core::GridWindow>{};
  std::size_t most = 0;
  int rounds = 0, corners_alone = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::string at = what + ", frame " + std::to_string(f);
    const std::vector<float>& s = *frames[f].state;
    const lod::NodePositions all = lod::interleaved_positions(s.data(), rows, cols);
    const lod::TileRanges ranges = lod::tile_ranges(all);
    const std::size_t na = full.build(all, ranges, camera_of(frames[f].camera), 1.0, a);
    PartialHost host(s, rows, cols);
    host.start_frame(kept);
    std::size_t nb = 0;
    EXPECT_NO_THROW(nb = partial.build(host.positions(), ranges, camera_of(frames[f].camera), 1.0, b)) << at;
    EXPECT_EQ(nb, na) << at;
    EXPECT_TRUE(std::equal(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(na), b.begin())) << at;
    EXPECT_EQ(partial.stats().brought, static_cast<std::size_t>(host.rounds)) << at;
    for (std::size_t k = 0; k < nb; ++k) {
      const std::uint32_t v = b[k];
      EXPECT_EQ(partial.world_x()[v], full.world_x()[v]) << at;
      EXPECT_EQ(partial.world_y()[v], full.world_y()[v]) << at;
      EXPECT_EQ(partial.world_z()[v], full.world_z()[v]) << at;
    }
    most = std::max(most, host.held_nodes());
    if (f > 0) rounds += host.rounds, corners_alone += host.corners_alone;
    kept = partial.reads();
  }
  if (most_held) *most_held = most;
  return {rounds, corners_alone};
}

TEST(LodFetch, TheSameMeshAsWithEveryNodeAtHand) {
  const int side = 257;
  const std::vector<float> rain = simulated_pond(side, side, 412, 20, 15, 1, 0.1);
  const std::vector<float> later = simulated_pond(side, side, 452, 20, 15, 1, 0.1);
  const CheckCamera whole_pond{{128, 35, -20}, {128, 0, 110}, 60, 1280, 720};
  const CheckCamera corner{{10, 3, 10}, {0, 0, 0}, 40, 640, 480};
  const CheckCamera grazing{{128, 1.5, 60}, {128, 0, 200}, 60, 1280, 720};
  // Blocks, then the whole grid (most blocks needed), then blocks again; the state changing.
  compare_builds(side, side,
                 {{&rain, corner}, {&rain, corner}, {&later, grazing}, {&later, whole_pond}, {&rain, whole_pond},
                  {&rain, corner}, {&later, corner}},
                 "257^2 rain");
  const int rows = 300, cols = 190;  // not 2^k + 1, not square
  const std::vector<float> waves = analytic_ripples(rows, cols, 6, 0.8, 3);
  compare_builds(rows, cols, {{&waves, {{95, 4, -5}, {95, 0, 150}, 60, 1280, 720}}, {&waves, corner}}, "300x190 waves");
}

TEST(LodFetch, ReadsOnlyTheBlocksItRefines) {
  const int side = 513;
  const std::vector<float> rain = simulated_pond(side, side, 300, 20, 15, 2, 0.1);
  const CheckCamera grazing{{256, 6, -10}, {256, 0, 300}, 60, 1280, 720};
  std::size_t most = 0;
  compare_builds(side, side, {{&rain, grazing}, {&rain, grazing}}, "513^2 rain", &most);
  EXPECT_LT(most, static_cast<std::size_t>(side) * side / 2);
  // From nothing held, it brings exactly what it reads (its blocks and its leaves' corners); the second build of the same state and view brings nothing: the first one's reads() hold it.
  lod::LodBuilder builder(side, side);
  std::vector<std::uint32_t> out(builder.max_indices());
  const lod::TileRanges ranges = lod::tile_ranges(lod::interleaved_positions(rain.data(), side, side));
  PartialHost host(rain, side, side);
  host.start_frame(std::vector<core::GridWindow>{});
  builder.build(host.positions(), ranges, camera_of(grazing), 1.0, out);
  EXPECT_GE(host.rounds, 1);
  ASSERT_TRUE(builder.reads().has_value());
  EXPECT_EQ(host.held_nodes(), core::NodeRuns(*builder.reads()).nodes());
  EXPECT_GT(builder.stats().blocks, 10u);
  host.start_frame(builder.reads());
  builder.build(host.positions(), ranges, camera_of(grazing), 1.0, out);
  EXPECT_EQ(host.rounds, 0);
  EXPECT_EQ(builder.stats().brought, 0u);
}

// Frame after frame of moving water (a step apart, the view held), each keeping what the last read:
// the few blocks a frame newly needs come in rounds that also bring the corners of the leaves the
// ranges accepted by then, so leaves' corners seldom need a round of their own (a wait on a GPU).
TEST(LodFetch, CornersComeWithTheBlocksOfTheirFrame) {
  const int side = 513;
  const CheckCamera grazing{{256, 6, -10}, {256, 0, 300}, 60, 1280, 720};
  std::vector<std::vector<float>> states;
  for (int settle = 15; settle < 23; ++settle) states.push_back(simulated_pond(side, side, 300, 20, settle, 2, 0.1));
  std::vector<Frame> frames;
  for (const std::vector<float>& s : states) frames.push_back({&s, grazing});
  const Rounds r = compare_builds(side, side, frames, "513^2 rain, moving");
  EXPECT_GT(r.rounds, 0);                              // new blocks are needed as the rings spread
  EXPECT_LE(r.rounds, static_cast<int>(frames.size()) - 1);  // one round a frame at most, here
  EXPECT_LE(r.corners_alone, 1);
}

}  // namespace
}  // namespace pond::lod_test
