// How long the tree's CPU parts take: growing it once (the demo's double-click) and one frame of the
// CPU bend (the reference the vertex shader is checked against; also a fallback that uploads bent
// positions, 40 KB per frame at depth 8).
#include <benchmark/benchmark.h>

#include "tree/bend.h"
#include "tree/tree.h"
#include "tree/wind_state.h"

namespace {
using namespace pond::tree;

void BM_GrowTree(benchmark::State& state) {
  const int depth = static_cast<int>(state.range(0));
  std::uint64_t seed = 0;
  for (auto _ : state) {
    Tree t = grow_tree({depth, ++seed, 1.0f});
    benchmark::DoNotOptimize(t.vertices.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(tree_vertex_count(depth)));
}
BENCHMARK(BM_GrowTree)->Arg(7)->Arg(8)->Unit(benchmark::kMicrosecond);

void BM_BendFrame(benchmark::State& state) {
  const Tree t = grow_tree({8, 1, 1.0f});
  const NoiseTable noise = make_noise_table(1);
  const UserWind user{5.0f, 0.4f, kWindPerStrength};
  const auto mode = static_cast<BendMode>(state.range(0));
  WindState wind;
  std::vector<Vec3> out(t.size());
  for (auto _ : state) {
    advance_wind(wind, noise, user, 1.0 / 60.0);
    bend_tree(t, wind_frame(wind, noise, user, mode), out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(t.size()));
  state.SetLabel(mode == BendMode::article ? "article" : "keep_length");
}
BENCHMARK(BM_BendFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
