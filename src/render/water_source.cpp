#include "render/water_source.h"

#include <cstring>
#include <string>

#include "gpu/water_layout.h"
#include "scene/body_fields.h"
#include "sim/normals.h"

namespace pond::render {
namespace {
using BU = vk::BufferUsageFlagBits;
}  // namespace

WaterSource::WaterSource(const gpu::Context& ctx, sim::Session& session, const gpu::GpuSolvers* gpu)
    : ctx_(ctx), session_(session), gpu_(gpu) {}

void WaterSource::sync() {
  sim::SolverReader solver = session_.reader();
  displacements_ = solver.displacements();  // waits
  tiles_ = solver.tile_bounds();            // of the same submission: no second wait
  bodies_ = solver.read_bodies();           // the same
}

const gpu::GpuSolver* WaterSource::session_gpu() const {
  const gpu::GpuSolver* g = gpu_ ? gpu_->live() : nullptr;
  return g && static_cast<const sim::Solver*>(g) == &session_.solver() ? g : nullptr;
}

WaterSource::DrawBuffers WaterSource::prepare(std::uint32_t slot) {
  if (const gpu::GpuSolver* g = session_gpu())
    return {&g->state_buffer(), &g->normals_buffer(), g->bodies_buffer(), static_cast<std::uint32_t>(g->stride()),
            static_cast<std::uint32_t>(g->pitch())};

  const sim::WaterModel& model = session_.model();
  const std::size_t nodes = model.nodes(), stride = gpu::state_stride(nodes);  // compact: rows cols nodes apart
  if (cpu_.empty()) {
    cpu_.resize(kFramesInFlight);
    for (std::uint32_t s = 0; s < kFramesInFlight; ++s) {
      // Storage buffers for the water's vertex shader, texel buffers for the caustics pass.
      const auto usage = BU::eStorageBuffer | BU::eUniformTexelBuffer;
      const std::string n = ", slot " + std::to_string(s);
      cpu_[s].state = gpu::create_buffer(ctx_, 3 * stride * sizeof(float), usage, gpu::MemoryUse::upload,
                                         "CPU water state" + n);
      cpu_[s].normals = gpu::create_buffer(ctx_, nodes * 4 * sizeof(float), usage, gpu::MemoryUse::upload,
                                           "CPU water normals" + n);
      cpu_[s].bodies = gpu::create_buffer(ctx_, scene::kMaxBodies * sizeof(sim::BodyState), BU::eVertexBuffer,
                                          gpu::MemoryUse::upload, "CPU bodies" + n);
    }
  }
  SlotBuffers& b = cpu_[slot];
  const sim::HostDisplacements& d = displacements_;
  auto* u = static_cast<float*>(b.state.mapped);
  const auto rows = static_cast<std::size_t>(model.rows), cols = static_cast<std::size_t>(model.cols);
  const float* const from[3] = {d.ux, d.uy, d.uz};
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < rows; ++i) std::memcpy(u + c * stride + i * cols, from[c] + i * d.pitch, cols * sizeof(float));
  const sim::Normals n = sim::compute_normals(d, model);
  auto* v = static_cast<float*>(b.normals.mapped);
  for (std::size_t k = 0; k < nodes; ++k) {
    v[4 * k] = n.x[k];
    v[4 * k + 1] = n.y[k];
    v[4 * k + 2] = n.z[k];
    v[4 * k + 3] = 0.0f;
  }
  b.state.flush(ctx_);
  b.normals.flush(ctx_);
  if (!bodies_.empty()) {
    std::memcpy(b.bodies.mapped, bodies_.data(), bodies_.size() * sizeof(sim::BodyState));
    b.bodies.flush(ctx_, bodies_.size() * sizeof(sim::BodyState));
  }
  return {&b.state, &b.normals, bodies_.empty() ? nullptr : &b.bodies, static_cast<std::uint32_t>(stride),
          static_cast<std::uint32_t>(cols)};
}

void WaterSource::keep_on_host(std::optional<std::vector<core::GridWindow>> lod_reads) {
  if (3 * sizeof(float) * session_.model().nodes() < kReadBackInPartsFrom) lod_reads.reset();
  session_.reader().keep_on_host(std::move(lod_reads));
}

lod::NodePositions WaterSource::positions() const {
  // The LOD builder converts the displacements to world positions as it copies them.
  const sim::WaterModel& model = session_.model();
  return lod::grid_displacements(displacements_.ux, displacements_.uy, displacements_.uz, model.rows, model.cols,
                                 model.spacing, displacements_.pitch);
}

}  // namespace pond::render
