#pragma once
// Foam (shaders/shared/foam.h): white water where the surface is stirred, a compute pass of its own
// outside the bit-exact physics. Each frame that draws foam updates it from the water's state over
// the steps simulated since the last update (a paused pond's foam stands still), ping-ponging two
// node-sized buffers; water.vert reads the newest (shared/water_render.h binding
// POND_RENDER_BINDING_FOAM). Nothing is made until the first frame with foam: a pond drawn without
// it has no foam buffers, no pipeline and records nothing. Water that goes back in time (reset to
// rest, an earlier state set) starts again without foam.
//
// A FramePass (render/frame_pass.h): it declares the buffer it writes, read by the water's vertex
// shader. The update also reads the last update's output, which the frame's first barrier
// (compute writes -> compute reads) orders.
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

  // Sets up slot `slot`'s update from the water `state` (water_gpu.h's layout, `stride` and
  // `pitch`) of `model` after `steps` steps (the physics as it is now: the panel edits Δt, mass and
  // stiffness), making the pass on its first call, and returns the buffer the update writes, which
  // the frame's water draws. The slot's last submissions must have finished.
  const gpu::Buffer& prepare(std::uint32_t slot, const gpu::Buffer& state, std::uint32_t stride, std::uint32_t pitch,
                             const sim::WaterModel& model, std::int64_t steps);
  // A frame without foam, after `steps` steps: nothing is recorded, but water that went back (a
  // reset) is noted, and the next update starts from the displacements it finds.
  void skip(std::int64_t steps);
  // The frame's pass: on where the plan has foam; the prepared update recorded.
  TimedPass timed() const override { return TimedPass::foam; }
  bool enabled(const FrameContext& frame) const override { return frame.plan.foam; }
  void declare(const FrameContext& frame, PassDeclaration& d) override;
  void record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) override;
  bool made() const { return static_cast<bool>(*pipeline_.pipeline); }
  std::size_t buffers_made() const { return made() ? buffers_.size() + 1 : 0; }  // with last_
  // The newest foam read back (waits for the device to be idle first; for tests and tools).
  std::vector<float> read();
  // What a new pass goes on from (the frame loop made again for new constraints, the same grid): the
  // foam read back, as read(), and the step of its update.
  struct Carried {
    std::vector<float> foam;
    std::optional<std::int64_t> steps;
  };
  Carried carry() { return {read(), last_steps_}; }
  // Before the first update: start from `c` instead of no foam (ignored unless it is rows * cols).
  void adopt(Carried c);

 private:
  void make();
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
