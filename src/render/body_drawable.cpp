#include "render/body_drawable.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "render/body_pipeline.h"
#include "render/sphere_mesh.h"
#include "shared/body_render.h"

namespace pond::render {
namespace {

namespace sh = shared::body_render;
using BU = vk::BufferUsageFlagBits;

// Three subdivisions (1280 triangles): a smooth outline at the sizes a body takes on screen, and
// a small part of a frame's vertices on llvmpipe even for the session's 64 bodies.
constexpr int kSphereSubdivisions = 3;

// Linear colours: a brick red for what pushes the water, a buoy yellow for what floats on it.
constexpr sh::vec4 kKinematic{0.42f, 0.07f, 0.04f, 0.0f};
constexpr sh::vec4 kFloating{0.78f, 0.5f, 0.06f, 0.0f};

sh::vec4 v4(const std::array<double, 3>& a) {
  return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2]), 0.0f};
}

}  // namespace

struct BodyDrawable::Impl {
  const gpu::Context& ctx;
  const FrameLoop& loop;
  BodyPipeline pipe;
  gpu::Buffer points, indices;
  std::uint32_t index_count = 0;
  std::vector<gpu::Buffer> instances;  // per frame slot, host-visible
  std::vector<bool> floating;          // per body, as last seen not held (a held body is kinematic)
  std::uint32_t count = 0;             // instances of the last prepared frame
  sh::BodyFrame frame{};

  Impl(const gpu::Context& c, const FrameLoop& l)
      : ctx(c), loop(l), pipe(create_body_pipeline(c, l.color_format(), FrameLoop::kDepthFormat)) {
    const SphereMesh mesh = build_sphere_mesh(kSphereSubdivisions);
    index_count = static_cast<std::uint32_t>(mesh.indices.size());
    points = gpu::create_buffer(ctx, mesh.points.size() * sizeof mesh.points[0], BU::eVertexBuffer | BU::eTransferDst,
                                gpu::MemoryUse::device, "body sphere points");
    gpu::upload(ctx, points, std::as_bytes(std::span(mesh.points)));
    indices = gpu::create_buffer(ctx, mesh.indices.size() * 4, BU::eIndexBuffer | BU::eTransferDst,
                                 gpu::MemoryUse::device, "body sphere indices");
    gpu::upload(ctx, indices, std::as_bytes(std::span(mesh.indices)));
    for (std::uint32_t k = 0; k < FrameLoop::kFramesInFlight; ++k)
      instances.push_back(gpu::create_buffer(ctx, kMaxBodies * sizeof(sh::BodyInstance), BU::eVertexBuffer,
                                             gpu::MemoryUse::upload, "body instances, slot " + std::to_string(k)));
  }

  void prepare(const FrameInfo& info) {
    const sim::Session& session = loop.session();
    const std::vector<sim::BodyState> states = session.bodies();
    const auto& specs = session.scene().bodies;
    const double h = session.model().spacing;
    count = static_cast<std::uint32_t>(std::min({states.size(), specs.size(), kMaxBodies}));
    floating.resize(count);
    std::vector<sh::BodyInstance> drawn(count);
    for (std::uint32_t b = 0; b < count; ++b) {
      const bool held = session.held(b);
      if (!held) floating[b] = specs[b].motion == sim::BodyMotion::floating;
      const sim::BodyState& s = states[b];
      drawn[b].sphere = {static_cast<float>(s.x * h), static_cast<float>(s.y * h), static_cast<float>(s.z * h),
                         static_cast<float>(specs[b].radius)};
      drawn[b].albedo = floating[b] ? kFloating : kKinematic;
      drawn[b].albedo.w = held ? 1.0f : 0.0f;
    }
    if (count > 0) {
      const gpu::Buffer& buffer = instances[info.slot];
      std::memcpy(buffer.mapped, drawn.data(), drawn.size() * sizeof drawn[0]);
      buffer.flush(ctx);
    }
    const auto& sun = info.lighting.sun;
    const double sl = std::sqrt(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
    std::memcpy(frame.view_proj.m, info.view_proj, sizeof frame.view_proj.m);
    frame.eye = {info.eye[0], info.eye[1], info.eye[2], 0.0f};
    frame.sun = v4({sun[0] / sl, sun[1] / sl, sun[2] / sl});
    frame.sky = v4(info.lighting.sky);
  }

  void draw(const FrameInfo& info) const {
    if (count == 0) return;
    const vk::raii::CommandBuffer& cmd = info.cmd;
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipe.pipeline);
    cmd.pushConstants<sh::BodyFrame>(*pipe.layout, vk::ShaderStageFlagBits::eVertex, 0, frame);
    const vk::Buffer buffers[] = {*points.buffer, *instances[info.slot].buffer};
    const vk::DeviceSize offsets[] = {0, 0};
    cmd.bindVertexBuffers(0, buffers, offsets);
    cmd.bindIndexBuffer(*indices.buffer, 0, vk::IndexType::eUint32);
    cmd.drawIndexed(index_count, count, 0, 0, 0);
  }
};

BodyDrawable::BodyDrawable(const gpu::Context& ctx, const FrameLoop& loop) : impl_(std::make_unique<Impl>(ctx, loop)) {}

// Frames in flight may still read the instance buffers.
BodyDrawable::~BodyDrawable() {
  if (impl_) impl_->ctx.device().waitIdle();
}

void BodyDrawable::prepare(const FrameInfo& frame) { impl_->prepare(frame); }
void BodyDrawable::draw(const FrameInfo& frame) { impl_->draw(frame); }
std::size_t BodyDrawable::drawn() const { return impl_->count; }
std::size_t BodyDrawable::sphere_triangles() const { return impl_->index_count / 3; }

}  // namespace pond::render
