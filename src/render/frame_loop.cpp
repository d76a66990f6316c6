#include "render/frame_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/errors.h"
#include "gpu/buffer.h"
#include "render/barrier_batch.h"
#include "render/caustics_pass.h"
#include "render/color_format.h"
#include "render/reflection_pass.h"
#include "render/shadow_pass.h"
#include "view/land_mesh.h"
#include "view/triangle_cull.h"
#include "render/render_layout.h"
#include "render/render_target.h"
#include "view/view_projection.h"
#include "render/water_pipeline.h"
#include "render/water_source.h"
#include "lod/lod_builder.h"

namespace pond::render {
namespace {

using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
using BU = vk::BufferUsageFlagBits;

// The full mesh, 2 (R-1)(C-1) triangles with one diagonal direction, counter-clockwise from +y.
std::vector<std::uint32_t> full_mesh_indices(int rows, int cols) {
  std::vector<std::uint32_t> idx;
  idx.reserve(static_cast<std::size_t>(rows - 1) * (cols - 1) * 6);
  for (int i = 0; i + 1 < rows; ++i)
    for (int j = 0; j + 1 < cols; ++j) {
      const auto a = static_cast<std::uint32_t>(i * cols + j), b = a + 1, c = a + static_cast<std::uint32_t>(cols), d = c + 1;
      idx.insert(idx.end(), {a, c, b, b, c, d});
    }
  return idx;
}

vk::ImageMemoryBarrier2 layout_barrier(vk::Image image, vk::ImageAspectFlags aspect, vk::ImageLayout from,
                                       vk::ImageLayout to, vk::PipelineStageFlags2 src_stage, vk::AccessFlags2 src_access,
                                       vk::PipelineStageFlags2 dst_stage, vk::AccessFlags2 dst_access) {
  return {.srcStageMask = src_stage, .srcAccessMask = src_access, .dstStageMask = dst_stage, .dstAccessMask = dst_access,
          .oldLayout = from, .newLayout = to, .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
          .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .image = image,
          .subresourceRange = {.aspectMask = aspect, .baseMipLevel = 0, .levelCount = 1, .baseArrayLayer = 0, .layerCount = 1}};
}

// xyz (or rgb) of a uniform vec4; w = 0 (a packed w lane is set by its name: POND_FRAME_*).
shared::water_render::vec4 v4(const std::array<double, 3>& a) {
  return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2]), 0.0f};
}

// How far the reflection shifts per unit of the surface normal's xz tilt, in screen widths and
// heights: ripples of a few degrees wobble it by a few pixels.
constexpr float kReflectionShift = 0.05f;

// The sun's shadow map: texels per unit over the camera's pixels per unit at the nearest caster (a
// shadow on the ground is stretched along the sunlight, and the filter spans two texels), and its
// largest size. The receivers' heights the shadows are looked for between: the floor and the land's
// top plus this much for wave crests.
constexpr double kShadowTexelsPerPixel = 1.5;
constexpr std::uint32_t kMaxShadowMapSize = 1024;
constexpr double kShadowWaveMargin = 1.0;

// One frame's shadow map: its view and the target's rectangles where its shadows can show.
struct FrameShadow {
  view::SunShadowView view;
  std::vector<view::PixelRect> rects;
};

vk::Rect2D scissor(const view::PixelRect& r) {
  return {{r.x0, r.y0}, {static_cast<std::uint32_t>(r.x1 - r.x0), static_cast<std::uint32_t>(r.y1 - r.y0)}};
}

// One draw list of a culled mesh (view/triangle_cull.h): the triangles inside the view volume, then
// those across its boundary, from the bound index buffer.
void draw_range(const vk::raii::CommandBuffer& cmd, const view::IndexRange& r) {
  if (r.inside > 0) cmd.drawIndexed(r.inside, 1, r.first, 0, 0);
  if (r.across > 0) cmd.drawIndexed(r.across, 1, r.first + r.inside, 0, 0);
}

// A non-indexed triangle list's vertices, structure of arrays, and its triangles (0, 1, 2, ...):
// what view::cull_triangles reads. `y_sign`: -1 for the mirrored walls, as land.vert mirrors them.
struct CullSource {
  std::vector<float> x, y, z;
  std::vector<std::uint32_t> triangles;
  view::MeshPositions positions() const { return {x, y, z}; }
};
CullSource cull_source(const std::vector<LandVertex>& mesh, float y_sign) {
  CullSource c;
  for (const LandVertex& p : mesh) {
    c.x.push_back(p.position.x);
    c.y.push_back(y_sign * p.position.y);
    c.z.push_back(p.position.z);
    c.triangles.push_back(static_cast<std::uint32_t>(c.triangles.size()));
  }
  return c;
}

// Writes `m`'s index lists into `b` (host-visible), made larger first if they do not fit; the
// buffer must be idle.
void write_indices(const gpu::Context& ctx, gpu::Buffer& b, const view::CulledMesh& m, const char* what,
                   std::uint32_t slot) {
  const vk::DeviceSize bytes = std::max<std::size_t>(1, m.indices.size()) * sizeof(std::uint32_t);
  if (!*b.buffer || b.size < bytes)
    b = gpu::create_buffer(ctx, std::max<vk::DeviceSize>(bytes, 2 * b.size), vk::BufferUsageFlagBits::eIndexBuffer,
                           gpu::MemoryUse::upload, std::string(what) + ", slot " + std::to_string(slot));
  std::memcpy(b.mapped, m.indices.data(), m.indices.size() * sizeof(std::uint32_t));
  b.flush(ctx, bytes);
}

double ms_since(std::chrono::steady_clock::time_point& t) {
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - t).count();
  t = now;
  return ms;
}

}  // namespace

// One frame slot: everything a frame in flight owns.
struct Slot {
  vk::raii::CommandBuffer early = nullptr;  // the passes before the main one (simulate())
  vk::raii::CommandBuffer cmd = nullptr;    // the main pass (draw())
  vk::raii::Fence early_done = nullptr;     // signalled when the slot's last early passes finished
  vk::raii::Fence done = nullptr;  // signalled when the slot's last draw finished
  gpu::Buffer uniforms;                 // host-visible: WaterFrame
  gpu::Buffer indices, land_indices;    // host-visible: the water's and the land's culled lists
  gpu::Buffer mirrored_land_indices;    // host-visible: the mirrored walls' (the reflection's)
  vk::raii::DescriptorSet set = nullptr;
  Image depth;
  ReflectionTarget reflection;
  Image shadow;  // the sun's shadow map (render/shadow_pass.h)
};

struct FrameLoop::Impl {
  const gpu::Context& ctx;
  sim::Session& session;
  view::LightingSpec lighting;
  vk::Format color_format;
  std::unique_ptr<WaterSource> water;
  std::uint64_t water_generation = 0;  // the session's solver_generation() `water` reads
  lod::LodBuilder lod;
  WaterPipelines pipes;
  vk::raii::Sampler reflection_sampler = nullptr;  // nearest, clamped: also the caustics map's
  vk::raii::Sampler shadow_sampler = nullptr;
  CausticsPass caustics;
  gpu::Buffer land, mirrored_land, full_indices;  // mirrored_land: the reflection's (view::mirrored_walls)
  std::uint32_t land_vertices = 0, full_index_count = 0;
  CullSource land_source, mirrored_source;  // for culling: the land's, the mirrored walls' (y negated)
  std::vector<std::uint32_t> lod_indices;      // the LOD's triangles before culling
  view::CulledMesh culled;                     // scratch
  vk::raii::CommandPool pool = nullptr;
  vk::raii::DescriptorPool descriptor_pool = nullptr;
  std::vector<Slot> slots;
  std::uint32_t next = 0;
  std::vector<PassDrawable*> drawables;

  Impl(const gpu::Context& c, sim::Session& drawn, vk::Format format)
      : ctx(c), session(drawn), lighting(drawn.scene().lighting), color_format(format),
        lod(drawn.model().rows, drawn.model().cols), pipes(create_water_pipelines(c, format, kDepthFormat)),
        caustics(c, drawn.model(), kFramesInFlight) {
    reflection_sampler = create_reflection_sampler(ctx);
    shadow_sampler = create_shadow_sampler(ctx);
    follow_solver();
    create_static_geometry();
    session.set_before_change([this] { wait_all(); });
    pool = vk::raii::CommandPool(ctx.device(), vk::CommandPoolCreateInfo{
                                                   .flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                   .queueFamilyIndex = ctx.queue_family()});
    const vk::DescriptorPoolSize sizes[] = {{.type = vk::DescriptorType::eUniformBuffer, .descriptorCount = kFramesInFlight},
                                            {.type = vk::DescriptorType::eStorageBuffer, .descriptorCount = 2 * kFramesInFlight},
                                            {.type = vk::DescriptorType::eCombinedImageSampler, .descriptorCount = 2 * kFramesInFlight}};
    descriptor_pool = vk::raii::DescriptorPool(
        ctx.device(), vk::DescriptorPoolCreateInfo{.flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                   .maxSets = kFramesInFlight, .poolSizeCount = 3, .pPoolSizes = sizes});
    vk::raii::CommandBuffers cmds(ctx.device(), vk::CommandBufferAllocateInfo{.commandPool = *pool,
                                                                              .level = vk::CommandBufferLevel::ePrimary,
                                                                              .commandBufferCount = 2 * kFramesInFlight});
    for (std::uint32_t k = 0; k < kFramesInFlight; ++k) {
      Slot s;
      s.early = std::move(cmds[2 * k]);
      s.cmd = std::move(cmds[2 * k + 1]);
      s.early_done = vk::raii::Fence(ctx.device(), vk::FenceCreateInfo{.flags = vk::FenceCreateFlagBits::eSignaled});
      s.done = vk::raii::Fence(ctx.device(), vk::FenceCreateInfo{.flags = vk::FenceCreateFlagBits::eSignaled});
      s.uniforms = gpu::create_buffer(ctx, sizeof(WaterFrame), BU::eUniformBuffer, gpu::MemoryUse::upload,
                                 "water frame uniforms, slot " + std::to_string(k));
      const vk::DescriptorSetLayout layout = *pipes.set_layout;
      s.set = std::move(vk::raii::DescriptorSets(ctx.device(), vk::DescriptorSetAllocateInfo{
                                                                   .descriptorPool = *descriptor_pool,
                                                                   .descriptorSetCount = 1, .pSetLayouts = &layout})[0]);
      slots.push_back(std::move(s));
    }
  }

  const sim::WaterModel& model() const { return session.model(); }  // may change with the solver

  // A WaterSource for the session's current solver (a new one after a switch or an edit).
  void follow_solver() {
    if (water && water_generation == session.solver_generation()) return;
    simulated.reset();  // its buffers are the old solver's
    wait_all();
    caustics.forget_water_buffers();
    water.reset();
    water = std::make_unique<WaterSource>(ctx, session.solver(), kFramesInFlight);
    water_generation = session.solver_generation();
  }

  void create_static_geometry() {
    const view::ViewSpec& v = session.scene().view;
    const std::vector<LandVertex> mesh = view::build_land_mesh(model(), v.floor_depth, v.land_height);
    land_vertices = static_cast<std::uint32_t>(mesh.size());
    land_source = cull_source(mesh, 1.0f);
    land = gpu::create_buffer(ctx, mesh.size() * sizeof(LandVertex), BU::eVertexBuffer | BU::eTransferDst, gpu::MemoryUse::device,
                         "land vertices");
    gpu::upload(ctx, land, std::as_bytes(std::span(mesh)));
    const std::vector<LandVertex> above = view::mirrored_walls(mesh);
    mirrored_source = cull_source(above, -1.0f);
    mirrored_land = gpu::create_buffer(ctx, std::max<std::size_t>(1, above.size()) * sizeof(LandVertex),
                                          BU::eVertexBuffer | BU::eTransferDst, gpu::MemoryUse::device, "land walls above the water");
    if (!above.empty()) gpu::upload(ctx, mirrored_land, std::as_bytes(std::span(above)));
    const std::vector<std::uint32_t> full = full_mesh_indices(model().rows, model().cols);
    full_index_count = static_cast<std::uint32_t>(full.size());
    full_indices = gpu::create_buffer(ctx, std::max<std::size_t>(1, full.size()) * 4, BU::eIndexBuffer | BU::eTransferDst,
                                 gpu::MemoryUse::device, "water full-mesh indices");
    gpu::upload(ctx, full_indices, std::as_bytes(std::span(full)));
  }

  void wait(const Slot& s) const {
    const vk::Fence fences[] = {*s.early_done, *s.done};
    if (ctx.device().waitForFences(fences, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
      throw RuntimeError("waiting for a frame failed");
  }
  void wait_all() const {
    for (const Slot& s : slots) wait(s);
  }

  // ---- The frame loop ----
  // What simulate() left for draw().
  struct Simulated {
    std::uint32_t slot = 0;
    FrameView view;
    lod::Camera camera;  // view.camera at the size the LOD and the early passes were made for
    std::array<float, 16> view_proj{};  // the camera's
    std::optional<FrameShadow> shadow;  // the sun's shadow map this frame, if any
    WaterSource::DrawBuffers bufs;
    std::size_t index_count = 0;  // the LOD's (or the full mesh's)
    // What the land's and the water's draws take of their index buffers: the whole view's and each
    // shadow rectangle's lists (view/triangle_cull.h).
    view::IndexRange land_whole, water_whole, mirrored_land;
    std::vector<view::IndexRange> land_rects, water_rects;
    FrameStats stats;
    std::uint64_t state_revision = 0;  // the session's when simulated
  };
  std::optional<Simulated> simulated;

  bool has_simulated() const {
    return simulated && simulated->state_revision == session.state_revision() &&
           water_generation == session.solver_generation();
  }

  FrameStats simulate(const FrameView& view, vk::Extent2D extent) {
    const std::uint32_t slot = next;
    Slot& s = slots[slot];
    wait(s);  // the slot's previous draw is done: its buffers may be rewritten
    Simulated f;
    f.slot = slot;
    f.view = view;
    f.stats.full_triangles = full_index_count / 3;
    f.stats.land_triangles = land_vertices / 3;
    auto t = std::chrono::steady_clock::now();
    session.advance(view.steps);  // 1. substeps
    follow_solver();              // (the session replaced its solver: a run past its ripples)
    f.bufs = water->prepare(slot);  // 2. normals, positions -> CPU
    f.state_revision = session.state_revision();
    f.stats.simulate_ms = ms_since(t);
    // 3. The passes before the main one, submitted now: the device draws them while the CPU builds
    // the LOD (they do not read it).
    set_up_frame(f, extent);
    record_early(s.early, s, f, true);
    submit_early(s);
    f.stats.draw_ms = ms_since(t);
    build_lod(f);  // 4. LOD into the slot's indices
    f.stats.lod_ms = ms_since(t);
    simulated = std::move(f);
    return simulated->stats;
  }

  // The frame's camera at `extent`, the drawables' and the water's per-frame state for it, and the
  // shadow map's fit: what every pass of the frame reads. The slot must be idle.
  void set_up_frame(Simulated& f, vk::Extent2D extent) {
    Slot& s = slots[f.slot];
    f.camera = f.view.camera;
    f.camera.width = static_cast<int>(extent.width);
    f.camera.height = static_cast<int>(extent.height);
    f.view_proj = view::view_projection(f.camera, model());
    ensure_reflection_target(ctx, s.reflection, extent);  // made even when off: the set is whole
    const FrameInfo info = frame_info(s.early, f);
    for (PassDrawable* d : drawables) d->prepare(info);
    f.shadow = f.view.effects.shadows ? fit_shadow(f.view_proj, extent) : std::nullopt;
    ensure_shadow_map(ctx, s.shadow, f.shadow ? f.shadow->view.size : 0);  // made even when off: the set is whole
    view::cull_triangles(land_source.triangles, land_source.positions(), f.view_proj, f.camera.width, f.camera.height,
                         shadow_pixels(f), culled);
    write_indices(ctx, s.land_indices, culled, "land indices", f.slot);
    f.land_whole = culled.whole;
    f.land_rects = culled.rects;
    if (f.view.effects.reflections) {
      const vk::Extent2D mirror = s.reflection.color.extent;
      view::cull_triangles(mirrored_source.triangles, mirrored_source.positions(), f.view_proj,
                           static_cast<int>(mirror.width), static_cast<int>(mirror.height), {}, culled);
      write_indices(ctx, s.mirrored_land_indices, culled, "mirrored walls' indices", f.slot);
      f.mirrored_land = culled.whole;
    }
    bind_buffers(f.slot, s, f.bufs);
    write_frame_uniforms(s, f.camera, f.view_proj, f.bufs.stride, f.bufs.pitch, f.shadow);
  }

  FrameInfo frame_info(const vk::raii::CommandBuffer& cmd, const Simulated& f) const {
    return {cmd, f.slot, f.view_proj.data(),
            {static_cast<float>(f.camera.eye[0]), static_cast<float>(f.camera.eye[1]),
             static_cast<float>(f.camera.eye[2])},
            {static_cast<std::uint32_t>(f.camera.width), static_cast<std::uint32_t>(f.camera.height)},
            static_cast<double>(session.steps_done()) * model().physics.dt, lighting};
  }

  static std::span<const view::PixelRect> shadow_pixels(const Simulated& f) {
    return f.shadow ? std::span<const view::PixelRect>(f.shadow->rects) : std::span<const view::PixelRect>();
  }

  // The LOD's triangles, culled into the slot's index buffer; without the LOD, the full mesh
  // (draw() draws full_indices whole).
  void build_lod(Simulated& f) {
    Slot& s = slots[f.slot];
    f.water_rects.clear();
    if (f.view.lod_tolerance_px <= 0) {
      f.index_count = full_index_count;
      f.water_whole = {0, full_index_count, 0};
      if (f.shadow) f.water_rects.assign(f.shadow->rects.size(), f.water_whole);
    } else {
      lod_indices.resize(lod.max_indices());
      f.index_count = lod.build(water->positions(), f.camera, f.view.lod_tolerance_px, lod_indices);
      view::cull_triangles(std::span(lod_indices).first(f.index_count),
                           {lod.world_x(), lod.world_y(), lod.world_z()}, f.view_proj, f.camera.width, f.camera.height,
                           shadow_pixels(f), culled);
      write_indices(ctx, s.indices, culled, "water LOD indices", f.slot);
      f.water_whole = culled.whole;
      f.water_rects = culled.rects;
    }
    f.stats.triangles = f.index_count / 3;
  }

  FrameStats draw(const FrameTarget& target) {
    if (!has_simulated()) throw InternalError("FrameLoop::draw without a simulated frame");
    Simulated f = std::move(*simulated);
    simulated.reset();
    Slot& s = slots[f.slot];
    next = (f.slot + 1) % kFramesInFlight;
    auto t = std::chrono::steady_clock::now();
    const bool resized = static_cast<std::uint32_t>(f.camera.width) != target.extent.width ||
                         static_cast<std::uint32_t>(f.camera.height) != target.extent.height;
    if (resized) {  // the window was resized between the halves: the early passes are drawn again
      wait(s);      // (the submitted ones may still read the slot's uniforms)
      set_up_frame(f, target.extent);
      build_lod(f);
      f.stats.lod_ms += ms_since(t);
    }
    const bool full = f.view.lod_tolerance_px <= 0;
    ensure_depth(s, target.extent);  // 5. draw
    s.cmd.reset();
    s.cmd.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
    if (resized) record_early(s.cmd, s, f, false);
    record_main(s, target, frame_info(s.cmd, f), full ? full_indices : s.indices, f);
    s.cmd.end();
    submit(s, target);
    if (f.view.wait) wait(s);
    f.stats.draw_ms += ms_since(t);
    return f.stats;
  }

  // The shadow map's view fitted to the drawables' casters this frame, with the parts of the target
  // its shadows can reach; nothing when nothing casts or no shadow is on screen.
  std::optional<FrameShadow> fit_shadow(const std::array<float, 16>& view_proj, vk::Extent2D extent) const {
    std::vector<view::ShadowCaster> casters;
    for (const PassDrawable* d : drawables) d->add_shadow_casters(casters);
    // As many texels per unit as the camera gives the nearest caster pixels (by its clip w, the
    // view depth; |m[5]| h / 2 pixels per unit at depth 1), kShadowTexelsPerPixel times.
    double pixels = 0.0;
    for (const view::ShadowCaster& c : casters) {
      double w = 0.0, reach = 0.0;  // the box centre's view depth; the box's half diagonal
      for (int k = 0; k < 3; ++k) {
        w += view_proj[3 + 4 * k] * 0.5 * (c.lo[k] + c.hi[k]);
        reach += 0.25 * (c.hi[k] - c.lo[k]) * (c.hi[k] - c.lo[k]);
      }
      const double depth = std::max(w + view_proj[15] - std::sqrt(reach), 1e-2);
      pixels = std::max(pixels, std::abs(view_proj[5]) * 0.5 * extent.height / depth);
    }
    const std::optional<view::SunShadowView> fitted =
        view::fit_sun_shadow(lighting.sun, casters, pixels * kShadowTexelsPerPixel, kMaxShadowMapSize);
    if (!fitted) return std::nullopt;
    const view::ViewSpec& v = session.scene().view;
    std::vector<view::PixelRect> rects;
    for (const view::ShadowCaster& c : casters)
      if (const auto r = view::shadow_pixels(*fitted, c, view_proj, static_cast<int>(extent.width),
                                             static_cast<int>(extent.height), -v.floor_depth,
                                             v.land_height + kShadowWaveMargin))
        rects.push_back(*r);
    rects = view::merge_overlapping(rects);
    if (rects.empty()) return std::nullopt;
    return FrameShadow{*fitted, std::move(rects)};
  }

  std::array<double, 3> unit_sun() const {
    const auto& d = lighting.sun;
    const double sl = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    return {d[0] / sl, d[1] / sl, d[2] / sl};
  }

  void write_frame_uniforms(const Slot& s, const lod::Camera& camera, const std::array<float, 16>& view_proj,
                            std::uint32_t stride, std::uint32_t pitch,
                            const std::optional<FrameShadow>& shadow) const {
    const view::LightingSpec& l = lighting;
    const view::ViewSpec& v = session.scene().view;
    WaterFrame f;
    std::memcpy(f.view_proj.m, view_proj.data(), sizeof f.view_proj.m);
    f.eye = v4(camera.eye);
    POND_FRAME_GRID_SPACING(f) = model().spacing;
    f.sun = v4(unit_sun());
    f.sky = v4(l.sky);
    f.water = v4(l.water);
    f.ground = v4(l.ground);
    POND_FRAME_FLOOR_DEPTH(f) = static_cast<float>(v.floor_depth);
    POND_FRAME_LAND_HEIGHT(f) = static_cast<float>(v.land_height);
    f.wire = {0.02f, 0.05f, 0.08f, 0.55f};
    POND_FRAME_ROWS(f) = static_cast<std::uint32_t>(model().rows);
    POND_FRAME_COLS(f) = static_cast<std::uint32_t>(model().cols);
    POND_FRAME_STATE_STRIDE(f) = stride;
    POND_FRAME_STATE_PITCH(f) = pitch;
    const view::SkyBox sky = view::sky_box(model(), v.land_height);
    f.sky_lo = v4(sky.lo);
    f.sky_hi = v4(sky.hi);
    f.screen = {1.0f / static_cast<float>(camera.width), 1.0f / static_cast<float>(camera.height), kReflectionShift, 0.0f};
    if (shadow) std::memcpy(f.shadow.m, shadow->view.texture.data(), sizeof f.shadow.m);
    const std::array<float, 3> under_water = view::sunlight_in_water(l.sun);
    f.shadow_sun = {under_water[0], under_water[1], under_water[2], 0.0f};
    const std::array<float, 4> c = caustics_lookup(model(), unit_sun());
    f.caustics = {c[0], c[1], c[2], c[3]};
    const vk::Extent2D map = caustics_extent(model().rows, model().cols);
    f.caustics_size = {map.width, map.height, 0, 0};
    std::memcpy(s.uniforms.mapped, &f, sizeof f);
    s.uniforms.flush(ctx);
  }

  // The slot's descriptor set points at this frame's buffers (the GPU solver's current ping-pong
  // buffer, or the slot's CPU copies); the slot is idle, so updating it is allowed. The caustics
  // pass reads the same buffers.
  void bind_buffers(std::uint32_t slot, const Slot& s, const WaterSource::DrawBuffers& b) {
    const vk::DescriptorBufferInfo infos[] = {s.uniforms.whole(), b.state->whole(), b.normals->whole()};
    const vk::DescriptorImageInfo reflection{.sampler = *reflection_sampler, .imageView = *s.reflection.color.view,
                                             .imageLayout = vk::ImageLayout::eShaderReadOnlyOptimal};
    const vk::DescriptorImageInfo shadow{.sampler = *shadow_sampler, .imageView = *s.shadow.view,
                                         .imageLayout = vk::ImageLayout::eShaderReadOnlyOptimal};
    const vk::DescriptorImageInfo caustics_map{.sampler = *reflection_sampler, .imageView = *caustics.map(slot).view,
                                               .imageLayout = vk::ImageLayout::eShaderReadOnlyOptimal};
    const vk::WriteDescriptorSet writes[] = {
        {.dstSet = *s.set, .dstBinding = POND_RENDER_BINDING_FRAME, .descriptorCount = 1,
         .descriptorType = vk::DescriptorType::eUniformBuffer, .pBufferInfo = &infos[0]},
        {.dstSet = *s.set, .dstBinding = POND_RENDER_BINDING_STATE, .descriptorCount = 1,
         .descriptorType = vk::DescriptorType::eStorageBuffer, .pBufferInfo = &infos[1]},
        {.dstSet = *s.set, .dstBinding = POND_RENDER_BINDING_NORMALS, .descriptorCount = 1,
         .descriptorType = vk::DescriptorType::eStorageBuffer, .pBufferInfo = &infos[2]},
        {.dstSet = *s.set, .dstBinding = POND_RENDER_BINDING_REFLECTION, .descriptorCount = 1,
         .descriptorType = vk::DescriptorType::eCombinedImageSampler, .pImageInfo = &reflection},
        {.dstSet = *s.set, .dstBinding = POND_RENDER_BINDING_SHADOW, .descriptorCount = 1,
         .descriptorType = vk::DescriptorType::eCombinedImageSampler, .pImageInfo = &shadow},
        {.dstSet = *s.set, .dstBinding = POND_RENDER_BINDING_CAUSTICS, .descriptorCount = 1,
         .descriptorType = vk::DescriptorType::eCombinedImageSampler, .pImageInfo = &caustics_map}};
    ctx.device().updateDescriptorSets(writes, nullptr);
    caustics.bind(slot, *b.state, *b.normals);
  }

  void ensure_depth(Slot& s, vk::Extent2D extent) const {
    if (*s.depth.image && s.depth.extent == extent) return;
    s.depth = create_image(ctx, extent, kDepthFormat, vk::ImageUsageFlagBits::eDepthStencilAttachment,
                           vk::ImageAspectFlagBits::eDepth, "depth");
  }

  // The sky at the horizon (water_shading.h's sky_color at d.y = 0): the background. A clear value
  // is stored as given, so for a UNORM target it is sRGB-encoded here, as the shaders encode theirs.
  std::array<float, 4> horizon_color(vk::Format format) const {
    const auto& z = lighting.sky;
    auto c = [&](int k) {
      const double linear = std::min(z[k] + (1.0 - z[k]) * 0.55, 1.0);
      if (is_srgb(format)) return static_cast<float>(linear);
      return static_cast<float>(linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055);
    };
    return {c(0), c(1), c(2), 1.0f};
  }

  // The passes before the main one (caustics, shadow map, reflection) into `cmd`: whole (begun,
  // ended) when `own`, else inside draw()'s. They read nothing another writes, so their barriers go
  // in two batches: one before them all, one after (render/barrier_batch.h).
  void record_early(const vk::raii::CommandBuffer& cmd, const Slot& s, const Simulated& f, bool own) const {
    if (own) {
      cmd.reset();
      cmd.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
    }
    const FrameInfo info = frame_info(cmd, f);
    const std::optional<FrameShadow>& shadow = f.shadow;
    const bool reflections = f.view.effects.reflections, caustics_on = f.view.effects.caustics;
    // Before: compute (substeps, normals) -> vertex shader (this pass's and the main one's, later in
    // submission order) and caustics reads of state and normals; each image to the layout it is
    // written in.
    BarrierBatch batch;
    batch.memory.push_back({.srcStageMask = S::eComputeShader, .srcAccessMask = A::eShaderWrite,
                            .dstStageMask = S::eVertexShader | S::eComputeShader, .dstAccessMask = A::eShaderRead});
    if (caustics_on) batch.images.push_back(caustics.begin_barrier(info.slot));
    if (shadow) batch.images.push_back(shadow_pass_begin(s.shadow));
    if (reflections)
      for (const vk::ImageMemoryBarrier2& b : reflection_pass_begin(s.reflection)) batch.images.push_back(b);
    batch.record(cmd);

    if (caustics_on)
      caustics.record_dispatch(cmd, info.slot, caustics_push(model(), unit_sun(), session.scene().view.floor_depth,
                                                             f.bufs.stride, f.bufs.pitch));
    if (shadow) {
      FrameInfo sun = info;
      sun.view_proj = shadow->view.clip.data();
      sun.extent = s.shadow.extent;
      record_shadow_pass(cmd, s.shadow, [&] {
        for (PassDrawable* d : drawables) d->draw_shadow(sun);
      });
    }
    if (reflections) {
      FrameInfo mirrored = info;
      mirrored.extent = s.reflection.color.extent;
      mirrored.pixel_scale = static_cast<float>(mirrored.extent.height) / static_cast<float>(info.extent.height);
      record_reflection_pass(cmd, s.reflection, [&] {
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipes.layout, 0, *s.set, nullptr);
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipes.land_mirror);
        cmd.bindVertexBuffers(0, *mirrored_land.buffer, vk::DeviceSize{0});
        cmd.bindIndexBuffer(*s.mirrored_land_indices.buffer, 0, vk::IndexType::eUint32);
        draw_range(cmd, f.mirrored_land);
        for (PassDrawable* d : drawables) d->draw_reflected(mirrored);
      });
    }
    // After: what they wrote to shader-read for the main pass's fragment shaders (a frame without
    // shadows still puts the map, which its set binds, in that layout).
    if (caustics_on) batch.images.push_back(caustics.end_barrier(info.slot));
    batch.images.push_back(shadow ? shadow_pass_end(s.shadow) : shadow_map_unused(s.shadow));
    if (reflections) batch.images.push_back(reflection_pass_end(s.reflection));
    batch.record(cmd);
    if (own) cmd.end();
  }

  void submit_early(const Slot& s) const {
    ctx.device().resetFences(*s.early_done);
    const vk::CommandBufferSubmitInfo cmd_info{.commandBuffer = *s.early};
    ctx.queue().submit2(vk::SubmitInfo2{.commandBufferInfoCount = 1, .pCommandBufferInfos = &cmd_info}, *s.early_done);
  }

  // The main pass into the caller's image, after the early passes in submission order.
  void record_main(const Slot& s, const FrameTarget& target, const FrameInfo& info, const gpu::Buffer& water_indices,
                   const Simulated& f) const {
    const vk::raii::CommandBuffer& cmd = info.cmd;
    const FrameView& view = f.view;
    const std::optional<FrameShadow>& shadow = f.shadow;
    const bool reflections = view.effects.reflections;
    // The target and the depth buffer to their attachment layouts. The color barrier waits at color
    // output, where the swapchain's acquire semaphore is waited.
    const vk::ImageMemoryBarrier2 images[] = {
        layout_barrier(target.image, vk::ImageAspectFlagBits::eColor, target.old_layout,
                       vk::ImageLayout::eColorAttachmentOptimal, S::eColorAttachmentOutput, {},
                       S::eColorAttachmentOutput, A::eColorAttachmentWrite | A::eColorAttachmentRead),
        layout_barrier(*s.depth.image, vk::ImageAspectFlagBits::eDepth, vk::ImageLayout::eUndefined,
                       vk::ImageLayout::eDepthAttachmentOptimal, S::eLateFragmentTests,
                       A::eDepthStencilAttachmentWrite, S::eEarlyFragmentTests | S::eLateFragmentTests,
                       A::eDepthStencilAttachmentRead | A::eDepthStencilAttachmentWrite)};
    cmd.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 2, .pImageMemoryBarriers = images});

    const vk::RenderingAttachmentInfo color{
        .imageView = target.view, .imageLayout = vk::ImageLayout::eColorAttachmentOptimal,
        .loadOp = vk::AttachmentLoadOp::eClear, .storeOp = vk::AttachmentStoreOp::eStore,
        .clearValue = vk::ClearValue{.color = {.float32 = horizon_color(target.format)}}};
    const vk::RenderingAttachmentInfo depth{
        .imageView = *s.depth.view, .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
        .loadOp = vk::AttachmentLoadOp::eClear, .storeOp = vk::AttachmentStoreOp::eDontCare,
        .clearValue = vk::ClearValue{.depthStencil = {.depth = 1.0f, .stencil = 0}}};
    cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, target.extent}, .layerCount = 1,
                                         .colorAttachmentCount = 1, .pColorAttachments = &color,
                                         .pDepthAttachment = &depth});
    cmd.setViewport(0, vk::Viewport{0, 0, static_cast<float>(target.extent.width),
                                    static_cast<float>(target.extent.height), 0, 1});
    cmd.setScissor(0, vk::Rect2D{{0, 0}, target.extent});
    for (PassDrawable* d : drawables) d->draw_occluding(info);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipes.layout, 0, *s.set, nullptr);
    // The land and the water: first where a shadow can fall (shadow->rects, scissored) with the
    // pipelines that sample the map, then everywhere with those that do not. Both test depth with
    // "less" before shading, and a pixel the first draw shaded holds a depth the second cannot beat
    // (the same `precise` vertex code, and the first draw's small bias toward the camera:
    // water_pipeline.cpp), so each pixel is shaded once. llvmpipe runs both sides of a per-pixel
    // branch, so only the scissor keeps the fetches off the pixels no shadow reaches; and one full
    // draw, not the rectangles' complement, keeps the vertex work to one pass over the mesh plus,
    // per rectangle, the triangles that can reach it (view/triangle_cull.h: each list in two draws,
    // the triangles inside the view volume, then those across its boundary).
    const vk::Rect2D whole{{0, 0}, target.extent};
    auto draw_range = [&](const view::IndexRange& r) { render::draw_range(cmd, r); };
    auto shaded = [&](const vk::raii::Pipeline& plain, const vk::raii::Pipeline& shadowed, const view::IndexRange& all,
                      const std::vector<view::IndexRange>& in_rects) {
      bool covered = false;  // a rectangle is the whole target (a low sun, a caster behind the eye)
      if (shadow) {
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *shadowed);
        for (std::size_t k = 0; k < shadow->rects.size(); ++k) {
          const vk::Rect2D r = scissor(shadow->rects[k]);
          cmd.setScissor(0, r);
          draw_range(in_rects[k]);
          covered = covered || r == whole;
        }
        cmd.setScissor(0, whole);
      }
      if (covered) return;
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *plain);
      draw_range(all);
    };
    cmd.bindVertexBuffers(0, *land.buffer, vk::DeviceSize{0});
    cmd.bindIndexBuffer(*s.land_indices.buffer, 0, vk::IndexType::eUint32);
    shaded(pipes.land, pipes.land_shadowed, f.land_whole, f.land_rects);
    cmd.bindIndexBuffer(*water_indices.buffer, 0, vk::IndexType::eUint32);
    const bool caustics_on = view.effects.caustics;
    shaded(pipes.water_for(reflections, caustics_on, false), pipes.water_for(reflections, caustics_on, true),
           f.water_whole, f.water_rects);
    if (view.wireframe && *pipes.wire) {
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipes.wire);
      draw_range(f.water_whole);
    }
    for (PassDrawable* d : drawables) d->draw(info);
    // Last, so only where nothing is; the drawables bound sets of their own.
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipes.layout, 0, *s.set, nullptr);
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipes.sky);
    cmd.draw(30, 1, 0, 0);  // sky.vert's box
    cmd.endRendering();

    // The image to its final layout; and the next frame's substeps must not overwrite the state
    // or normals while this draw (or the caustics pass) reads them (write-after-read: an execution
    // dependency).
    const bool present = target.final_layout == vk::ImageLayout::ePresentSrcKHR;
    const vk::ImageMemoryBarrier2 end_image = layout_barrier(
        target.image, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eColorAttachmentOptimal, target.final_layout,
        S::eColorAttachmentOutput, A::eColorAttachmentWrite, present ? S::eNone : S::eCopy,
        present ? A::eNone : A::eTransferRead);
    const vk::MemoryBarrier2 vertex_to_compute{.srcStageMask = S::eVertexShader | S::eComputeShader,
                                               .dstStageMask = S::eComputeShader | S::eCopy};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &vertex_to_compute,
                                            .imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &end_image});
  }

  void submit(const Slot& s, const FrameTarget& target) const {
    ctx.device().resetFences(*s.done);
    const vk::CommandBufferSubmitInfo cmd_info{.commandBuffer = *s.cmd};
    const vk::SemaphoreSubmitInfo wait_info{.semaphore = target.wait_semaphore, .stageMask = S::eColorAttachmentOutput};
    const vk::SemaphoreSubmitInfo signal_info{.semaphore = target.signal_semaphore, .stageMask = S::eAllCommands};
    ctx.queue().submit2(vk::SubmitInfo2{.waitSemaphoreInfoCount = target.wait_semaphore ? 1u : 0u,
                                        .pWaitSemaphoreInfos = &wait_info,
                                        .commandBufferInfoCount = 1, .pCommandBufferInfos = &cmd_info,
                                        .signalSemaphoreInfoCount = target.signal_semaphore ? 1u : 0u,
                                        .pSignalSemaphoreInfos = &signal_info},
                        *s.done);
  }
};

FrameLoop::FrameLoop(const gpu::Context& ctx, sim::Session& session, vk::Format color_format)
    : impl_(std::make_unique<Impl>(ctx, session, color_format)) {}

FrameLoop::~FrameLoop() {
  if (!impl_) return;
  impl_->session.set_before_change({});
  impl_->wait_all();
}

FrameStats FrameLoop::frame(const FrameTarget& target, const FrameView& view) {
  impl_->simulate(view, target.extent);
  return impl_->draw(target);
}
FrameStats FrameLoop::simulate(const FrameView& view, vk::Extent2D extent) { return impl_->simulate(view, extent); }
bool FrameLoop::simulated() const { return impl_->has_simulated(); }
FrameStats FrameLoop::draw(const FrameTarget& target) { return impl_->draw(target); }
void FrameLoop::wait_idle() const { impl_->wait_all(); }

void FrameLoop::set_sun(const std::array<double, 3>& toward_sun) { impl_->lighting.sun = toward_sun; }
void FrameLoop::add_drawable(PassDrawable& drawable) { impl_->drawables.push_back(&drawable); }

const sim::Session& FrameLoop::session() const { return impl_->session; }
const scene::Scene& FrameLoop::scene() const { return impl_->session.scene(); }
const sim::WaterModel& FrameLoop::model() const { return impl_->session.model(); }
vk::Format FrameLoop::color_format() const { return impl_->color_format; }

lod::Camera FrameLoop::default_camera(int width, int height) const {
  return view::scene_camera(impl_->session.scene().camera, impl_->session.model(), width, height);
}

}  // namespace pond::render
