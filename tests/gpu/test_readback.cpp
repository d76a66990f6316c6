// The GPU solver's displacements on the host in parts (GpuSolver::keep_on_host, bring_to_host;
// gpu/displacement_readback.h): the nodes kept and brought have the state's bits, after every
// submission, and only they are held where the state is not read in place (a discrete GPU; CI runs
// this under the discrete-GPU layer too). Where it is read in place (lavapipe) every node is.
#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/node_runs.h"
#include "gpu/gpu_solver.h"
#include "gpu_fixture.h"
#include "sim/test_util.h"

namespace pond::test {
namespace {

// "" when every node of `windows` in `d` has the bits of `s`, else the first that does not.
std::string differs(const sim::HostDisplacements& d, const sim::WaterState& s, int cols,
                    const std::vector<core::GridWindow>& windows) {
  for (const core::GridWindow& w : windows)
    for (int r = w.row0; r < w.row0 + w.rows; ++r)
      for (int c = w.col0; c < w.col0 + w.cols; ++c) {
        const std::size_t host = static_cast<std::size_t>(r) * d.pitch + static_cast<std::size_t>(c);
        const std::size_t k = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
        if (std::bit_cast<std::uint32_t>(d.ux[host]) != std::bit_cast<std::uint32_t>(s.ux[k]) ||
            std::bit_cast<std::uint32_t>(d.uy[host]) != std::bit_cast<std::uint32_t>(s.uy[k]) ||
            std::bit_cast<std::uint32_t>(d.uz[host]) != std::bit_cast<std::uint32_t>(s.uz[k]))
          return "node (" + std::to_string(r) + ", " + std::to_string(c) + ")";
      }
  return "";
}

TEST_F(GpuTest, DisplacementsHoldTheNodesKeptAndBrought) {
  const int rows = 70, cols = 95;  // rows padded to 96 nodes on the GPU
  scene::Scene sc = grid_scene(rows, cols);
  for (int k = 0; k < 6; ++k) sc.perturbations.push_back(splash(7 + 9 * k, 11 + 13 * k, 2.5, 0.8, 2 * k));
  gpu::GpuSolver gpu(ctx(), sim::build_model(sc), true);
  const bool in_place = gpu::host_readable_in_place(ctx(), gpu.state_buffer());
  const core::GridWindow all{0, 0, rows, cols};
  const std::vector<core::GridWindow> kept = {{3, 5, 10, 20}, {40, 60, 30, 35}, {69, 0, 1, 95}, {0, 94, 70, 1}};
  gpu.keep_on_host(kept);
  gpu.advance(5);
  sim::HostDisplacements d = gpu.displacements();
  sim::WaterState s = gpu.read_state();
  EXPECT_EQ(differs(d, s, cols, kept), "");
  for (const core::GridWindow& w : kept) EXPECT_TRUE(gpu.holds_on_host(w));
  EXPECT_EQ(gpu.holds_on_host(all), in_place);
  EXPECT_EQ(gpu.holds_on_host({20, 30, 5, 5}), in_place);
  EXPECT_EQ(gpu.holds_on_host({3, 4, 1, 1}), in_place);  // beside a kept window

  const std::vector<core::GridWindow> brought = {{20, 30, 5, 5}, {0, 0, 70, 2}, {3, 4, 2, 30}};
  gpu.bring_to_host(brought);
  d = gpu.displacements();
  EXPECT_EQ(differs(d, s, cols, brought), "");
  EXPECT_EQ(differs(d, s, cols, kept), "");
  for (const core::GridWindow& w : brought) EXPECT_TRUE(gpu.holds_on_host(w));

  gpu.advance(4);  // a new state: the kept nodes again, not the brought ones
  d = gpu.displacements();
  s = gpu.read_state();
  EXPECT_EQ(differs(d, s, cols, kept), "");
  EXPECT_EQ(gpu.holds_on_host({20, 30, 5, 5}), in_place);

  gpu.keep_on_host(std::vector<core::GridWindow>{});  // nothing, then every node brought at once
  gpu.advance(1);
  EXPECT_EQ(gpu.holds_on_host({3, 5, 1, 1}), in_place);
  d = gpu.all_displacements();
  s = gpu.read_state();
  EXPECT_EQ(differs(d, s, cols, {all}), "");

  gpu.keep_on_host(std::nullopt);  // every node again
  gpu.advance(2);
  d = gpu.displacements();
  s = gpu.read_state();
  EXPECT_TRUE(gpu.holds_on_host(all));
  EXPECT_EQ(differs(d, s, cols, {all}), "");
}

}  // namespace
}  // namespace pond::test
