#include "render/water_source.h"

#include <cstring>
#include <stdexcept>

#include "core/errors.h"
#include "gpu/water_layout.h"
#include "sim/normals.h"

namespace pond::render {

using BU = vk::BufferUsageFlagBits;

WaterSource::WaterSource(const gpu::Context& ctx, sim::Solver& solver, std::uint32_t slots)
    : ctx_(ctx), model_(solver.model()), gpu_(dynamic_cast<gpu::GpuSolver*>(&solver)),
      cpu_(dynamic_cast<const sim::CpuSolver*>(&solver)) {
  if (!gpu_ && !cpu_) throw InternalError("WaterSource: an unknown kind of solver");
  const sim::WaterModel& model = model_;
  if (gpu_) {
    if (!gpu_->host_state())  // else read in place (lavapipe)
      readback_ = gpu::create_buffer(ctx, 3 * gpu_->stride() * sizeof(float), BU::eTransferDst, gpu::MemoryUse::readback,
                                "water positions readback");
  } else {
    const std::size_t stride = gpu::state_stride(model.nodes());  // compact: the rows cols nodes apart
    for (std::uint32_t s = 0; s < slots; ++s) {
      // Storage buffers for the water's vertex shader, texel buffers for the caustics pass.
      const auto usage = BU::eStorageBuffer | BU::eUniformTexelBuffer;
      slot_state_.push_back(gpu::create_buffer(ctx, 3 * stride * sizeof(float), usage, gpu::MemoryUse::upload,
                                          "CPU water state, slot " + std::to_string(s)));
      slot_normals_.push_back(gpu::create_buffer(ctx, model.nodes() * 4 * sizeof(float), usage,
                                            gpu::MemoryUse::upload, "CPU water normals, slot " + std::to_string(s)));
    }
  }
}

WaterSource::DrawBuffers WaterSource::prepare(std::uint32_t slot) {
  const std::size_t nodes = model_.nodes();
  if (gpu_) {
    const std::size_t stride = gpu_->stride();
    const float* u = gpu_->host_state();
    if (u) {
      gpu_->advance_for_frame(0, nullptr);
      u = gpu_->host_state();  // the current buffer of the ping-pong pair
    } else {
      gpu_->advance_for_frame(0, &readback_);
      readback_.invalidate(ctx_);
      u = static_cast<const float*>(readback_.mapped);
    }
    displacements_ = {u, u + stride, u + 2 * stride};
    displacements_pitch_ = gpu_->pitch();
    return {&gpu_->state_buffer(), &gpu_->normals_buffer(), static_cast<std::uint32_t>(stride),
            static_cast<std::uint32_t>(gpu_->pitch())};
  }
  const std::size_t stride = gpu::state_stride(nodes);
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
  slot_state_[slot].flush(ctx_);
  slot_normals_[slot].flush(ctx_);
  displacements_ = {s.ux.data(), s.uy.data(), s.uz.data()};
  displacements_pitch_ = static_cast<std::size_t>(model_.cols);
  return {&slot_state_[slot], &slot_normals_[slot], static_cast<std::uint32_t>(stride),
          static_cast<std::uint32_t>(model_.cols)};
}

lod::NodePositions WaterSource::positions() const {
  // The LOD builder converts the displacements to world positions as it copies them.
  return lod::grid_displacements(displacements_[0], displacements_[1], displacements_[2], model_.rows, model_.cols,
                                 model_.spacing, displacements_pitch_);
}

}  // namespace pond::render
