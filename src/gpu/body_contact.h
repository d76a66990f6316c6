#pragma once
// The GPU side of the bodies in the water: the contact pass (water_contact.comp, one small
// dispatch after each substep's step dispatch), the bodies' state on the GPU, their constants,
// and the schedule of the kinematic bodies' positions for the substeps of one submission (computed
// on the CPU by sim::kinematic_state, so both solvers use the same floats).
#include <cstdint>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/context.h"
#include "sim/model.h"

namespace pond::gpu {

// The contact shader's invocations for a device of this subgroup size: the largest power of two
// not above it that divides the reduction's 64 lanes (any choice gives the same bits).
std::uint32_t contact_invocations(std::uint32_t subgroup_size);

class BodyContact {
 public:
  // For the bodies of `model` (which must outlive this, as the context, the buffers and the views)
  // on the solver's two state buffers (rows `pitch` nodes apart, components `stride` floats
  // apart), their R32F views, the kinds' RGBA8UI view and the step shader's reach (which the pass
  // sets back to 0); `max_substeps` is the most substeps one submission records, and `regions`
  // how many submissions may be in flight at once (each reads its own region of the schedule).
  BodyContact(const Context& ctx, const sim::WaterModel& model, std::size_t pitch, std::size_t stride,
              const Buffer (&state)[2], const vk::raii::BufferView (&state_r32)[2],
              const vk::raii::BufferView& kinds_rgba8, const Buffer& reach, std::int64_t max_substeps,
              std::uint32_t regions, bool denorm_preserve);

  void set_bodies(const std::vector<sim::BodyState>& bodies);  // uploads them (waits)
  void upload_constants();  // the model's bodies' constants, where they changed (waits then)
  // The kinematic bodies' positions for the substeps of steps [first_step, first_step + steps),
  // written and flushed into `region` for the next submission (at most max_substeps substeps; no
  // submission in flight may read that region).
  void write_schedule(std::int64_t first_step, std::int64_t steps, std::uint32_t region);
  // The contact after the `substep_in_batch`-th substep since `region`'s write_schedule(), on state
  // buffer `cur` (the one that substep wrote); a compute barrier must follow it.
  void record(const vk::raii::CommandBuffer& cmd, int cur, std::uint32_t region, std::int64_t substep_in_batch) const;
  // The bodies' states on the GPU (storage, transfer source, instance-rate vertex buffer: the
  // renderer draws them from here).
  const Buffer& bodies() const { return bodies_; }

 private:
  const Context& ctx_;
  const sim::WaterModel& model_;
  std::size_t pitch_, stride_;
  std::int64_t max_substeps_;
  ComputePipeline pipe_;
  Buffer bodies_, constants_, schedule_, land_;
  std::vector<shared::BodyConstants> uploaded_;       // what constants_ holds
  vk::raii::DescriptorPool pool_ = nullptr;
  std::vector<vk::raii::DescriptorSet> sets_;  // sets_[c]: state buffer c
};

}  // namespace pond::gpu
