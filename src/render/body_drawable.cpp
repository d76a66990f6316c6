#include "render/body_drawable.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "render/body_pipeline.h"
#include "render/reflection_pass.h"
#include "render/shadow_pass.h"
#include "render/frame_constants.h"
#include "render/sphere_mesh.h"
#include "render/submerged_pass.h"
#include "scene/body_fields.h"
#include "shared/body_render.h"

namespace pond::render {
namespace {

namespace sh = shared::body_render;
using BU = vk::BufferUsageFlagBits;

// The sphere's levels of detail: 1 to 4 subdivisions (80 to 5120 triangles). Each body is drawn
// at the coarsest level whose outline stays within kOutlinePixels of the true sphere's at its size
// on screen: llvmpipe pays every triangle's setup, and a ball across the pond is a few pixels.
constexpr int kFirstSubdivision = 1, kLevels = 4;
constexpr double kOutlinePixels = 0.5;

struct Level {
  std::uint32_t first_index = 0, index_count = 0;
  std::int32_t vertex_offset = 0;
  double longest_edge = 0;  // unit sphere
};

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
  BodyPipeline pipe, mirror_pipe, submerged_pipe, shadow_pipe;  // the frame's, the layers', the shadow map's
  gpu::Buffer points, indices;
  std::array<Level, kLevels> levels{};
  std::vector<gpu::Buffer> instances;  // per frame slot, host-visible
  std::vector<bool> floating;          // per body, as last seen not held (a held body is kinematic)
  std::uint32_t count = 0;             // instances of the last prepared frame
  std::vector<int> level_of;           // per instance of the last prepared frame
  std::vector<sh::vec4> spheres;       // per instance of the last prepared frame (world)
  sh::BodyFrame frame{};

  Impl(const gpu::Context& c, const FrameLoop& l)
      : ctx(c), loop(l), pipe(create_body_pipeline(c, l.color_format(), kDepthFormat)),
        mirror_pipe(create_body_pipeline(c, kReflectionFormat, kDepthFormat, BodyView::mirrored)),
        submerged_pipe(create_body_pipeline(c, kSubmergedFormat, kDepthFormat, BodyView::submerged)),
        shadow_pipe(create_body_pipeline(c, vk::Format::eUndefined, kShadowFormat, BodyView::shadow)) {
    SphereMesh all;  // every level, one after the other
    for (int k = 0; k < kLevels; ++k) {
      const SphereMesh mesh = build_sphere_mesh(kFirstSubdivision + k);
      levels[k] = {static_cast<std::uint32_t>(all.indices.size()), static_cast<std::uint32_t>(mesh.indices.size()),
                   static_cast<std::int32_t>(all.points.size()), longest_edge(mesh)};
      all.points.insert(all.points.end(), mesh.points.begin(), mesh.points.end());
      all.indices.insert(all.indices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    points = gpu::create_buffer(ctx, all.points.size() * sizeof all.points[0], BU::eVertexBuffer | BU::eTransferDst,
                                gpu::MemoryUse::device, "body sphere points");
    gpu::upload(ctx, points, std::as_bytes(std::span(all.points)));
    indices = gpu::create_buffer(ctx, all.indices.size() * 4, BU::eIndexBuffer | BU::eTransferDst,
                                 gpu::MemoryUse::device, "body sphere indices");
    gpu::upload(ctx, indices, std::as_bytes(std::span(all.indices)));
    for (std::uint32_t k = 0; k < kFramesInFlight; ++k)
      instances.push_back(gpu::create_buffer(ctx, scene::kMaxBodies * sizeof(sh::BodyInstance), BU::eVertexBuffer,
                                             gpu::MemoryUse::upload, "body instances, slot " + std::to_string(k)));
  }

  // The coarsest level whose outline is within kOutlinePixels for a sphere (centre c, radius r,
  // world) seen through view_proj on a target `height` pixels high. Clip w is the view depth, and
  // |m[5]| h / 2 the pixels per world unit at unit depth; a sphere around the eye gets the finest.
  int level_for(const float* m, const sh::vec4& sphere, std::uint32_t height) const {
    const double w = m[3] * sphere.x + m[7] * sphere.y + m[11] * sphere.z + m[15];
    if (w <= sphere.w) return kLevels - 1;
    const double radius_px = std::fabs(m[5]) * 0.5 * height * sphere.w / (w - sphere.w);  // its nearest point
    for (int l = 0; l < kLevels; ++l)
      if (outline_error_px(radius_px, levels[l].longest_edge) <= kOutlinePixels) return l;
    return kLevels - 1;
  }

  void prepare(const FrameInfo& info) {
    const sim::Session& session = info.session;
    const std::span<const sim::BodyState> states = info.body_states;  // the host's copy of what is drawn
    const auto& specs = session.water().bodies;
    const double h = session.model().spacing;
    count = info.bodies ? static_cast<std::uint32_t>(std::min({states.size(), specs.size(), scene::kMaxBodies})) : 0;
    floating.resize(count);
    level_of.assign(count, 0);
    std::vector<sh::BodyInstance> drawn(count);
    spheres.resize(count);
    for (std::uint32_t b = 0; b < count; ++b) {
      const bool held = session.held(b);
      if (!held) floating[b] = specs[b].motion == sim::BodyMotion::floating;
      const sim::BodyState& s = states[b];
      spheres[b] = {static_cast<float>(s.x * h), static_cast<float>(s.y * h), static_cast<float>(s.z * h),
                    static_cast<float>(specs[b].radius)};
      drawn[b].size = {static_cast<float>(specs[b].radius), static_cast<float>(h), 0.0f, 0.0f};
      drawn[b].albedo = floating[b] ? kFloating : kKinematic;
      drawn[b].albedo.w = held ? 1.0f : 0.0f;
      level_of[b] = level_for(info.view_proj, spheres[b], info.extent.height);
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

  // With `with` (pipe; mirror_pipe, submerged_pipe in those layers' passes; shadow_pipe in the shadow map's,
  // whose projection is info.view_proj).
  void draw(const FrameInfo& info, const BodyPipeline& with) const {
    if (count == 0) return;
    const vk::raii::CommandBuffer& cmd = info.cmd;
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *with.pipeline);
    sh::BodyFrame pushed = frame;
    std::memcpy(pushed.view_proj.m, info.view_proj, sizeof pushed.view_proj.m);
    cmd.pushConstants<sh::BodyFrame>(*with.layout, vk::ShaderStageFlagBits::eVertex, 0, pushed);
    const vk::Buffer buffers[] = {*points.buffer, *instances[info.slot].buffer, *info.bodies->buffer};
    const vk::DeviceSize offsets[] = {0, 0, 0};
    cmd.bindVertexBuffers(0, buffers, offsets);
    cmd.bindIndexBuffer(*indices.buffer, 0, vk::IndexType::eUint32);
    for (std::uint32_t b = 0; b < count; ++b) {  // instance b: its own level
      const Level& l = levels[level_of[b]];
      cmd.drawIndexed(l.index_count, 1, l.first_index, l.vertex_offset, b);
    }
  }
};

BodyDrawable::BodyDrawable(const gpu::Context& ctx, const FrameLoop& loop) : impl_(std::make_unique<Impl>(ctx, loop)) {}

// Frames in flight may still read the instance buffers.
BodyDrawable::~BodyDrawable() {
  if (impl_) impl_->ctx.wait_idle_for_teardown();
}

void BodyDrawable::prepare(const FrameInfo& frame) { impl_->prepare(frame); }
void BodyDrawable::draw(const FrameInfo& frame) { impl_->draw(frame, impl_->pipe); }
void BodyDrawable::draw_reflected(const FrameInfo& frame) { impl_->draw(frame, impl_->mirror_pipe); }
void BodyDrawable::draw_submerged(const FrameInfo& frame) { impl_->draw(frame, impl_->submerged_pipe); }
void BodyDrawable::add_shadow_casters(std::vector<view::ShadowCaster>& casters) const {
  for (const sh::vec4& s : impl_->spheres) casters.push_back(view::sphere_caster({s.x, s.y, s.z}, s.w));
}
void BodyDrawable::draw_shadow(const FrameInfo& frame) { impl_->draw(frame, impl_->shadow_pipe); }
std::size_t BodyDrawable::drawn() const { return impl_->count; }
std::size_t BodyDrawable::triangles() const {
  std::size_t n = 0;
  for (const int l : impl_->level_of) n += impl_->levels[l].index_count / 3;
  return n;
}

}  // namespace pond::render
