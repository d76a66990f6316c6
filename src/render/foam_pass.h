#pragma once
// Foam (shaders/shared/foam.h): white water where the surface is stirred, a compute pass of its own
// outside the bit-exact physics. Each frame that draws foam updates it from the water's state over
// the steps simulated since the last update (a paused pond's foam stands still), ping-ponging two
// node-sized buffers; water.vert reads the newest (its binding and lane: shared/foam.h). Nothing is
// made until the first frame with foam: a pond drawn without it has no foam buffers, no pipeline
// and records nothing. Water that goes back in time (reset to rest, an earlier state set) starts
// again without foam.
//
// A FramePass (render/frame_pass.h), all of the effect but its drawing (water.vert, water.frag) and
// its switch (view::kEffects): it declares the buffer it writes, read by the water's vertex shader,
// binds it into the water's set and sets its lane of the frame's uniforms. The update also reads
// the last update's output, which the frame's first barrier (compute writes -> compute reads)
// orders.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/context.h"
#include "render/frame_pass.h"
#include "shared/foam.h"
#include "sim/model.h"

namespace pond::render {

class FoamPass final : public FramePass {
 public:
  FoamPass(const gpu::Context& ctx, const sim::WaterModel& model, std::uint32_t slots);

  // The frame's pass: on where the frame's effects have foam. prepare() sets up the slot's update
  // (making the pass on the first frame with foam) or, without foam, notes water that went back;
  // record() records the update.
  const char* name() const override { return "foam"; }
  bool enabled(const FrameContext& frame) const override { return frame.plan.effects.foam; }
  void declare(const FrameContext& frame, PassDeclaration& d) override;
  void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) override;
  void water_bindings(std::vector<vk::DescriptorSetLayoutBinding>& out) const override;
  void prepare(const FrameContext& frame) override;
  void bind_water(const FrameContext& frame, WaterSetWrites& set, WaterFrame& uniforms) override;
  std::size_t targets_made() const override { return made() ? buffers_.size() + 1 : 0; }  // with last_
  // The foam read back (as read()) and the step of its update, as a Carried; adopt() takes one
  // before the first update: the new pass starts from it instead of no foam (ignored unless it is
  // rows * cols).
  std::any carry() override;
  void adopt(std::any carried) override;
  struct Carried {
    std::vector<float> foam;
    std::optional<std::int64_t> steps;
  };

  bool made() const { return static_cast<bool>(*pipeline_.pipeline); }
  // The newest foam read back (waits for the device to be idle first; for tests and tools).
  std::vector<float> read();

 private:
  void make();
  // Sets up slot `slot`'s update from the water `state` (water_gpu.h's layout, `stride` and
  // `pitch`) of `model` after `steps` steps (the physics as it is now: the panel edits Δt, mass and
  // stiffness), and returns the buffer it writes. The slot's last submissions must have finished.
  const gpu::Buffer& update(std::uint32_t slot, const gpu::Buffer& state, std::uint32_t stride, std::uint32_t pitch,
                            const sim::WaterModel& model, std::int64_t steps);
  // A frame without foam, after `steps` steps: nothing is recorded, but water that went back (a
  // reset) is noted, and the next update starts from the displacements it finds.
  void skip(std::int64_t steps);
  // Water at `steps`, fewer than at the last update, went back: it starts again without foam.
  void went_back(std::int64_t steps);

  const gpu::Context& ctx_;
  std::uint32_t rows_, cols_, slots_;
  gpu::ComputePipeline pipeline_;
  vk::raii::DescriptorPool pool_ = nullptr;
  std::vector<vk::raii::DescriptorSet> sets_;  // per slot, written each update
  std::vector<shared::foam::FoamPush> pushes_;  // per slot, the prepared update's
  std::array<gpu::Buffer, 2> buffers_;
  gpu::Buffer last_;           // the displacements at the last update
  bool primed_ = false;        // last_ holds them
  std::uint32_t current_ = 0;  // the newest update's buffer
  bool filled_ = false;        // the buffers' first contents recorded
  gpu::Buffer seed_;           // adopt()'s foam, copied into both buffers at the first update
  bool seeded_ = false;        // seed_ holds what the next first contents are
  std::optional<std::int64_t> last_steps_;  // at the last update
};

}  // namespace pond::render
