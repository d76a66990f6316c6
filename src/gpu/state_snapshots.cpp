#include "gpu/state_snapshots.h"

#include <cstring>

#include "gpu/water_layout.h"

namespace pond::gpu {

StateSnapshots::StateSnapshots(const Context& ctx, int rows, int cols, std::size_t pitch, std::size_t stride,
                               std::size_t bodies)
    : ctx_(ctx), rows_(rows), cols_(cols), pitch_(pitch), stride_(stride), bodies_(bodies) {
  readback_ = create_buffer(ctx, kComponents * stride * sizeof(float) + bodies * sizeof(sim::BodyState),
                            vk::BufferUsageFlagBits::eTransferDst, MemoryUse::readback, "state snapshot readback");
}

void StateSnapshots::set(const sim::WaterState& state, std::int64_t step) {
  latest_.state = state;
  latest_.step = step;
  pending_serial_ = 0;
  since_ = 0;
}

bool StateSnapshots::due(std::int64_t substeps) {
  since_ += substeps;
  return interval_ > 0 && pending_serial_ == 0 && since_ >= interval_;
}

void StateSnapshots::record(const vk::raii::CommandBuffer& cmd, const Buffer& state, const Buffer* bodies,
                            std::uint64_t serial, std::int64_t step) {
  const vk::DeviceSize state_bytes = kComponents * stride_ * sizeof(float);
  cmd.copyBuffer(*state.buffer, *readback_.buffer, vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = state_bytes});
  if (bodies && bodies_ > 0)
    cmd.copyBuffer(*bodies->buffer, *readback_.buffer,
                   vk::BufferCopy{.srcOffset = 0, .dstOffset = state_bytes,
                                  .size = bodies_ * sizeof(sim::BodyState)});
  pending_serial_ = serial;
  pending_step_ = step;
  since_ = 0;
}

void StateSnapshots::harvest(std::uint64_t finished) {
  if (pending_serial_ == 0 || finished < pending_serial_) return;
  readback_.invalidate(ctx_);
  const auto* words = static_cast<const float*>(readback_.mapped);
  sim::WaterState& s = latest_.state;
  const auto rows = static_cast<std::size_t>(rows_), cols = static_cast<std::size_t>(cols_);
  if (s.nodes() != rows * cols) s = sim::WaterState(rows * cols);
  float* const dst[kComponents] = {s.ux.data(), s.uy.data(), s.uz.data(), s.vx.data(), s.vy.data(), s.vz.data()};
  for (unsigned c = 0; c < kComponents; ++c)  // drops the padding, as sim::WaterState
    for (std::size_t i = 0; i < rows; ++i)
      std::memcpy(dst[c] + i * cols, words + c * stride_ + i * pitch_, cols * sizeof(float));
  s.bodies.resize(bodies_);
  if (bodies_ > 0) std::memcpy(s.bodies.data(), words + kComponents * stride_, bodies_ * sizeof(sim::BodyState));
  latest_.step = pending_step_;
  pending_serial_ = 0;
}

}  // namespace pond::gpu
