#include "gpu/water_source.h"

#include <cstring>

#include "gpu/water_layout.h"
#include "sim/normals.h"

namespace pond::gpu {

using BU = vk::BufferUsageFlagBits;

WaterSource::WaterSource(const Context& ctx, const sim::WaterModel& model, const SolverChoice& choice,
                         std::uint32_t slots)
    : ctx_(ctx), model_(model), x_(model.nodes()), y_(model.nodes()), z_(model.nodes()) {
  const std::size_t stride = state_stride(model.nodes());
  if (choice.gpu) {
    gpu_.emplace(ctx, model);
    readback_ = create_buffer(ctx, 3 * stride * sizeof(float), BU::eTransferDst, MemoryUse::readback,
                              "water positions readback");
  } else {
    cpu_.emplace(model, choice.backend, choice.threads);
    for (std::uint32_t s = 0; s < slots; ++s) {
      slot_state_.push_back(create_buffer(ctx, 3 * stride * sizeof(float), BU::eStorageBuffer, MemoryUse::upload,
                                          "CPU water state, slot " + std::to_string(s)));
      slot_normals_.push_back(create_buffer(ctx, model.nodes() * 4 * sizeof(float), BU::eStorageBuffer,
                                            MemoryUse::upload, "CPU water normals, slot " + std::to_string(s)));
    }
  }
}

void WaterSource::advance(std::int64_t steps) {
  if (gpu_) gpu_->advance(steps);
  else cpu_->advance(steps);
}

WaterSource::DrawBuffers WaterSource::prepare(std::uint32_t slot) {
  const std::size_t nodes = model_.nodes(), stride = state_stride(nodes);
  if (gpu_) {
    gpu_->compute_normals();
    const Buffer& state = gpu_->state_buffer();
    ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
      // compute_normals() ended with a compute -> vertex/transfer barrier covering the state too.
      cmd.copyBuffer(*state.buffer, *readback_.buffer, vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = readback_.size});
      const vk::MemoryBarrier2 to_host{.srcStageMask = vk::PipelineStageFlagBits2::eCopy,
                                       .srcAccessMask = vk::AccessFlagBits2::eTransferWrite,
                                       .dstStageMask = vk::PipelineStageFlagBits2::eHost,
                                       .dstAccessMask = vk::AccessFlagBits2::eHostRead};
      cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
    });
    readback_.invalidate(ctx_);
    const auto* u = static_cast<const float*>(readback_.mapped);
    to_world(u, u + stride, u + 2 * stride);
    return {&state, &gpu_->normals_buffer(), static_cast<std::uint32_t>(stride)};
  }
  const sim::WaterState& s = cpu_->state();
  auto* u = static_cast<float*>(slot_state_[slot].mapped);
  std::memcpy(u, s.ux.data(), nodes * sizeof(float));
  std::memcpy(u + stride, s.uy.data(), nodes * sizeof(float));
  std::memcpy(u + 2 * stride, s.uz.data(), nodes * sizeof(float));
  const sim::Normals n = sim::compute_normals(s, model_);
  auto* v = static_cast<float*>(slot_normals_[slot].mapped);
  for (std::size_t k = 0; k < nodes; ++k) {
    v[4 * k] = n.x[k];
    v[4 * k + 1] = n.y[k];
    v[4 * k + 2] = n.z[k];
    v[4 * k + 3] = 0.0f;
  }
  to_world(s.ux.data(), s.uy.data(), s.uz.data());
  return {&slot_state_[slot], &slot_normals_[slot], static_cast<std::uint32_t>(stride)};
}

void WaterSource::to_world(const float* ux, const float* uy, const float* uz) {
  const float h = model_.spacing;
  const std::size_t cols = static_cast<std::size_t>(model_.cols);
  for (std::size_t n = 0; n < model_.nodes(); ++n) {
    x_[n] = (static_cast<float>(n % cols) + ux[n]) * h;
    y_[n] = uy[n] * h;
    z_[n] = (static_cast<float>(n / cols) + uz[n]) * h;
  }
}

lod::NodePositions WaterSource::positions() const {
  return lod::soa_positions(x_.data(), y_.data(), z_.data(), model_.rows, model_.cols);
}

sim::WaterState WaterSource::state() const { return gpu_ ? gpu_->read_state() : cpu_->state(); }

std::int64_t WaterSource::steps_done() const { return gpu_ ? gpu_->steps_done() : cpu_->steps_done(); }

void WaterSource::set_state(const sim::WaterState& state, std::int64_t steps_done) {
  if (gpu_) gpu_->set_state(state, steps_done);
  else cpu_->set_state(state, steps_done);
}

}  // namespace pond::gpu
