#pragma once
// Caustics on the pool floor, a FramePass (render/frame_pass.h) on where the frame's plan has them:
// one compute dispatch (shaders/shared/caustics.h) turns this frame's water state and normals into
// a small floor-space map of the sun's light relative to calm water, which water.frag multiplies the
// floor and the submerged walls it sees through the water by (one nearest fetch a pixel; its
// binding: shared/caustics.h). The map is per frame slot (a storage image written by the compute
// pass, sampled by the water), written and read in the slot's own command buffer, so a frame in
// flight keeps its own. Nothing is made until the first frame with caustics; until a slot's map is
// first written, the water's binding holds the frame's 1 x 1 placeholder, which no pipeline of such
// a frame samples. Between frames a written map rests in eShaderReadOnlyOptimal.
#include <array>
#include <utility>
#include <cstdint>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/context.h"
#include "render/frame_pass.h"
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

class CausticsPass final : public FramePass {
 public:
  // Makes nothing yet (make(): at the first frame with caustics, or the first bind()).
  CausticsPass(const gpu::Context& ctx, const sim::WaterModel& model, std::uint32_t slots);

  // The frame's pass. prepare() lets go of the slot's views of a replaced solver's buffers (a later
  // buffer may reuse a handle; the slot is finished) and, with caustics, binds the slot to this
  // frame's water; record() computes the map with the frame's sun.
  const char* name() const override { return "caustics"; }
  bool enabled(const FrameContext& frame) const override { return frame.plan.caustics; }
  void declare(const FrameContext& frame, PassDeclaration& d) override;
  void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) override;
  void water_bindings(std::vector<vk::DescriptorSetLayoutBinding>& out) const override;
  void prepare(const FrameContext& frame) override;
  void bind_water(const FrameContext& frame, WaterSetWrites& set, WaterFrame& uniforms) override;
  std::size_t targets_made() const override { return made() ? slots_.size() : 0; }  // the maps

  // Outside a frame (tests and tools): points slot `slot`'s descriptor set at the water buffers
  // (the slot must be idle), making the pass first; records the dispatch and the barriers around
  // it (the map from fragment-shader reads to the compute write and back; the state and normals
  // must be visible to compute shader reads: the caller's barrier).
  void bind(std::uint32_t slot, const gpu::Buffer& state, const gpu::Buffer& normals);
  void record(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, const CausticsPush& push);

  bool made() const { return !slots_.empty(); }
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
    // of each (the GPU solver's two state buffers and its normals, or the CPU path's copies), and
    // the session's solver they are of.
    std::vector<std::pair<vk::Buffer, vk::raii::BufferView>> views;
    std::uint64_t generation = 0;
    bool written = false;  // by a frame: it rests in shader-read since
  };
  void make();
  vk::BufferView view_of(Slot& slot, const gpu::Buffer& buffer, vk::Format format);
  void record_dispatch(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, const CausticsPush& push) const;

  const gpu::Context& ctx_;
  vk::Extent2D extent_;           // the maps'
  std::uint32_t slot_count_;
  vk::raii::Sampler sampler_ = nullptr;  // nearest: the water's texelFetch
  gpu::ComputePipeline pipeline_;
  vk::raii::DescriptorPool pool_ = nullptr;
  std::vector<Slot> slots_;
};

}  // namespace pond::render
