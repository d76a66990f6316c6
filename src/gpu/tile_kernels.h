#pragma once
// The tile bounds (shared/tile_bounds.h) of the GPU solver's state, made only while tracked
// (GpuSolver::track_tile_bounds): in place of the plain normals pass, its tile variant
// (water_normals.comp with POND_NORMALS_TILES) also writes each column's bounds over each tile
// row, where the state already streams; then water_tiles.comp merges a tile's columns. The normals
// pass runs last in a submission, after the steps, the contact and the splashes, so nothing moves
// a node between the bounds and the state they describe.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/context.h"
#include "gpu/water_kernels.h"
#include "sim/model.h"
#include "sim/tile_bounds.h"

namespace pond::gpu {

class TileKernels {
 public:
  // For the solver's kernels (their views of the state) and normals buffer, which must outlive
  // this, as the context; `slots`: the submissions that may be in flight (each its host copy).
  TileKernels(const Context& ctx, const sim::WaterModel& model, const WaterKernels& water, const Buffer& normals,
              bool denorm_preserve, std::uint32_t slots);

  // The normals of state c with the tile bounds (for WaterKernels::record_normals, with its
  // barriers before and after the normals), and their copy for the host into `slot`'s where the
  // bounds are not read in place. The submission's closing barrier must follow, which makes them
  // visible to the host, later commands and transfers (GpuSolver::record_copies).
  void record(const vk::raii::CommandBuffer& cmd, int c, std::uint32_t slot);
  // The bounds the submission of `slot` left, on the host (it must have finished).
  std::span<const TileBounds> host_bounds(std::uint32_t slot);

  // Tile (a, b) at b * tiles_x + a; storage and transfer source.
  const Buffer& bounds() const { return bounds_; }

 private:
  const Context& ctx_;
  const WaterKernels& water_;
  sim::TileGrid grid_;
  Buffer columns_, bounds_;  // columns_: per tile row b and column j at texels 2 (b * cols + j), +1
  // Per slot, the host's copy of bounds_ (none where bounds_ is mapped: read in place, lavapipe),
  // and whether it was invalidated since its submission finished.
  std::vector<Buffer> host_;
  std::vector<bool> host_seen_;
  ComputePipeline normals_pipe_, tiles_pipe_;
  vk::raii::DescriptorPool pool_ = nullptr;
  std::vector<vk::raii::DescriptorSet> normals_sets_;  // [c]: state c
  vk::raii::DescriptorSet tiles_set_ = nullptr;
  vk::raii::BufferView columns_rgba_ = nullptr;
};

}  // namespace pond::gpu
