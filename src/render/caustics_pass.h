#pragma once
// Caustics on the pool floor (frame_loop.h records it before the draw when
// FrameView::effects.caustics is on): one compute dispatch (shaders/shared/caustics.h) turns this
// frame's water state and normals into a small floor-space map of the sun's light relative to calm
// water, which water.frag multiplies the floor and the submerged walls it sees through the water by
// (one nearest fetch a pixel). The map is per frame slot (a storage image written by the compute
// pass, sampled by the water), written and read in the slot's own command buffer, so a frame in
// flight keeps its own.
//
// Between frames the map rests in eShaderReadOnlyOptimal (it is made so, filled with 1 = calm
// water, when created), so the water's descriptor is valid whether or not the pass ran.
#include <array>
#include <utility>
#include <cstdint>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/context.h"
#include "render/render_target.h"
#include "shared/caustics.h"
#include "sim/model.h"
#include "view/caustics_grid.h"

namespace pond::render {

using shared::caustics::CausticsPush;
static_assert(sizeof(CausticsPush) == 80 && offsetof(CausticsPush, light) == 16 &&
              offsetof(CausticsPush, grid) == 32 && offsetof(CausticsPush, map) == 48 &&
              offsetof(CausticsPush, coarse) == 64);

inline constexpr vk::Format kCausticsFormat = vk::Format::eR8G8B8A8Unorm;  // shared/caustics.h kCausticsUnit

class CausticsPass {
 public:
  CausticsPass(const gpu::Context& ctx, const sim::WaterModel& model, std::uint32_t slots);

  // Points slot `slot`'s descriptor set at this frame's water buffers (the slot must be idle).
  void bind(std::uint32_t slot, const gpu::Buffer& state, const gpu::Buffer& normals);
  // Slot `slot`'s views of the water's buffers, handed over when those buffers are replaced (a new
  // solver: a later buffer may reuse a handle): the slot's frame in flight may still read them, so
  // the caller keeps them until the slot is finished (FrameRing::retire).
  std::vector<vk::raii::BufferView> take_views(std::uint32_t slot);
  // Records the dispatch and the barriers around it: the map from fragment-shader reads to the
  // compute write and back. The state and normals must be visible to compute shader reads (the
  // caller's barrier).
  void record(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, const CausticsPush& push) const;
  // The same in parts, for a caller that batches the barriers with other passes'
  // (render/barrier_batch.h): the map to the compute write, the dispatch, the map to shader-read.
  vk::ImageMemoryBarrier2 begin_barrier(std::uint32_t slot) const;
  void record_dispatch(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, const CausticsPush& push) const;
  vk::ImageMemoryBarrier2 end_barrier(std::uint32_t slot) const;

  const Image& map(std::uint32_t slot) const { return slots_[slot].map; }
  // Copies slot `slot`'s map back (waits for the device to be idle first) and decodes it: width x
  // height floats, the light relative to calm water at each texel's first corner (x, y), row y =
  // map row y (for tests and tools).
  std::vector<float> read_map(std::uint32_t slot);

 private:
  struct Slot {
    Image map;
    vk::raii::DescriptorSet set = nullptr;
    // Texel-buffer views of the water's buffers this slot's set was pointed at, made on first use
    // of each (the GPU solver's two state buffers and its normals, or the CPU path's copies).
    std::vector<std::pair<vk::Buffer, vk::raii::BufferView>> views;
  };
  vk::BufferView view_of(Slot& slot, const gpu::Buffer& buffer, vk::Format format);

  const gpu::Context& ctx_;
  gpu::ComputePipeline pipeline_;
  vk::raii::DescriptorPool pool_ = nullptr;
  std::vector<Slot> slots_;
};

}  // namespace pond::render
