#include "gpu/body_contact.h"

#include <cstddef>
#include <cstring>

#include "core/errors.h"
#include "gpu/shaders.h"
#include "shared/bodies.h"
#include "sim/contact.h"

namespace pond::gpu {
namespace {

using BU = vk::BufferUsageFlagBits;
using shared::BodyConstants;
using shared::BodyState;
using shared::ContactPush;

static_assert(sizeof(BodyState) == 28 && offsetof(BodyState, vx) == 12 && offsetof(BodyState, flags) == 24);
static_assert(sizeof(BodyConstants) == 44 && offsetof(BodyConstants, inv_radius) == 8 &&
              offsetof(BodyConstants, gravity_dt) == 28 && offsetof(BodyConstants, drag_dt) == 36 &&
              offsetof(BodyConstants, floating) == 40);
static_assert(sizeof(ContactPush) == 52 && offsetof(ContactPush, schedule_first) == 20 &&
              offsetof(ContactPush, dt) == 24 && offsetof(ContactPush, rim_z) == 32 &&
              offsetof(ContactPush, floor_y) == 36 && offsetof(ContactPush, bounce_speed) == 48);

constexpr std::uint32_t kSets = 2;  // one per state buffer

}  // namespace

std::uint32_t contact_invocations(std::uint32_t subgroup_size) {
  std::uint32_t n = 1;
  while (n * 2 <= subgroup_size && n * 2 <= POND_CONTACT_LANES) n *= 2;
  return n;
}

BodyContact::BodyContact(const Context& ctx, const sim::WaterModel& model, std::size_t pitch, std::size_t stride,
                         const Buffer (&state)[2], const vk::raii::BufferView (&state_r32)[2],
                         const vk::raii::BufferView& kinds_rgba8, const Buffer& reach, std::int64_t max_substeps,
                         std::uint32_t regions, bool denorm_preserve)
    : ctx_(ctx), model_(model), pitch_(pitch), stride_(stride), max_substeps_(max_substeps) {
  std::vector<vk::DescriptorType> bindings(POND_CONTACT_BINDINGS, vk::DescriptorType::eStorageBuffer);
  bindings[POND_CONTACT_BINDING_STATE1] = bindings[POND_CONTACT_BINDING_KINDS4] = vk::DescriptorType::eUniformTexelBuffer;
  const SpecConstant local_x[] = {{POND_SPEC_CONTACT_LOCAL_X, contact_invocations(ctx_.subgroup_size())}};
  pipe_ = create_compute_pipeline(ctx_, water_contact_spirv(denorm_preserve), bindings, sizeof(ContactPush), local_x,
                                  "water_contact (" + std::to_string(local_x[0].value) + " invocations)");
  const std::size_t count = model_.bodies.size();
  bodies_ = create_buffer(ctx_, count * sizeof(BodyState),
                          BU::eStorageBuffer | BU::eTransferSrc | BU::eTransferDst | BU::eVertexBuffer,
                          MemoryUse::device, "bodies");
  constants_ = create_buffer(ctx_, count * sizeof(BodyConstants), BU::eStorageBuffer | BU::eTransferDst,
                             MemoryUse::device, "body constants");
  upload_constants();
  schedule_ = create_buffer(ctx_, static_cast<vk::DeviceSize>(max_substeps_) * regions * count * sizeof(BodyState),
                            BU::eStorageBuffer, MemoryUse::upload, "kinematic body schedule");
  land_ = create_buffer(ctx_, model_.land.size() * sizeof(std::uint32_t), BU::eStorageBuffer | BU::eTransferDst,
                        MemoryUse::device, "land runs");
  upload(ctx_, land_, std::as_bytes(std::span(model_.land)));

  const vk::DescriptorPoolSize sizes[] = {
      {.type = vk::DescriptorType::eStorageBuffer, .descriptorCount = kSets * (POND_CONTACT_BINDINGS - 2)},
      {.type = vk::DescriptorType::eUniformTexelBuffer, .descriptorCount = kSets * 2}};
  pool_ = vk::raii::DescriptorPool(ctx_.device(),
                                   vk::DescriptorPoolCreateInfo{.flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                                .maxSets = kSets, .poolSizeCount = 2, .pPoolSizes = sizes});
  const vk::DescriptorSetLayout layouts[kSets] = {*pipe_.set_layout, *pipe_.set_layout};
  vk::raii::DescriptorSets sets(ctx_.device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *pool_,
                                                                             .descriptorSetCount = kSets,
                                                                             .pSetLayouts = layouts});
  for (auto& s : sets) sets_.push_back(std::move(s));
  for (std::uint32_t c = 0; c < kSets; ++c) {
    vk::DescriptorBufferInfo infos[POND_CONTACT_BINDINGS];
    vk::BufferView views[POND_CONTACT_BINDINGS] = {};
    infos[POND_CONTACT_BINDING_STATE] = state[c].whole();
    views[POND_CONTACT_BINDING_KINDS4] = *kinds_rgba8;
    views[POND_CONTACT_BINDING_STATE1] = *state_r32[c];
    infos[POND_CONTACT_BINDING_BODIES] = bodies_.whole();
    infos[POND_CONTACT_BINDING_CONSTANTS] = constants_.whole();
    infos[POND_CONTACT_BINDING_SCHEDULE] = schedule_.whole();
    infos[POND_CONTACT_BINDING_REACH] = reach.whole();
    infos[POND_CONTACT_BINDING_LAND] = land_.whole();
    std::vector<vk::WriteDescriptorSet> writes;
    for (std::uint32_t b = 0; b < POND_CONTACT_BINDINGS; ++b)
      if (bindings[b] == vk::DescriptorType::eStorageBuffer)
        writes.push_back({.dstSet = *sets_[c], .dstBinding = b, .descriptorCount = 1,
                          .descriptorType = bindings[b], .pBufferInfo = &infos[b]});
      else
        writes.push_back({.dstSet = *sets_[c], .dstBinding = b, .descriptorCount = 1,
                          .descriptorType = bindings[b], .pTexelBufferView = &views[b]});
    ctx_.device().updateDescriptorSets(writes, nullptr);
  }
}

void BodyContact::upload_constants() {
  std::vector<BodyConstants> constants;
  for (const sim::BodyModel& b : model_.bodies) constants.push_back(b.constants);
  // A drag changes only a path (the schedule) every frame: no upload and wait then.
  if (constants.size() == uploaded_.size() &&
      std::memcmp(constants.data(), uploaded_.data(), constants.size() * sizeof(BodyConstants)) == 0)
    return;
  upload(ctx_, constants_, std::as_bytes(std::span(constants)));
  uploaded_ = std::move(constants);
}

void BodyContact::set_bodies(const std::vector<sim::BodyState>& bodies) {
  if (bodies.size() != model_.bodies.size())
    throw InternalError("GpuSolver::set_state: " + std::to_string(bodies.size()) + " bodies for a model of " +
                     std::to_string(model_.bodies.size()));
  upload(ctx_, bodies_, std::as_bytes(std::span(bodies)));
}

void BodyContact::write_schedule(std::int64_t first_step, std::int64_t steps, std::uint32_t region) {
  const int substeps = model_.substeps;
  if (steps * substeps > max_substeps_) throw InternalError("BodyContact::write_schedule: too many substeps");
  const std::size_t count = model_.bodies.size();
  const std::size_t first = static_cast<std::size_t>(max_substeps_) * region * count;
  auto* entries = static_cast<BodyState*>(schedule_.mapped) + first;
  for (std::int64_t s = 0; s < steps; ++s)
    for (int k = 0; k < substeps; ++k)
      for (std::size_t b = 0; b < count; ++b)
        if (!model_.bodies[b].floating())
          entries[static_cast<std::size_t>(s * substeps + k) * count + b] =
              sim::kinematic_state(model_.bodies[b], first_step + s, k, substeps, model_.physics.dt);
  schedule_.flush_range(ctx_, first * sizeof(BodyState), static_cast<vk::DeviceSize>(steps * substeps) * count * sizeof(BodyState));
}

void BodyContact::record(const vk::raii::CommandBuffer& cmd, int cur, std::uint32_t region,
                         std::int64_t substep_in_batch) const {
  ContactPush push = sim::contact_push(model_);
  push.pitch = static_cast<std::uint32_t>(pitch_);
  push.stride = static_cast<std::uint32_t>(stride_);
  push.schedule_first = static_cast<std::uint32_t>(max_substeps_ * region + substep_in_batch) * push.count;
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipe_.pipeline);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipe_.layout, 0, *sets_[cur], nullptr);
  cmd.pushConstants<ContactPush>(*pipe_.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
  cmd.dispatch(1, 1, 1);
}

}  // namespace pond::gpu
