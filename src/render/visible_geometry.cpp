#include "render/visible_geometry.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace pond::render {
namespace {

using BU = vk::BufferUsageFlagBits;

// The full mesh, 2 (R-1)(C-1) triangles with one diagonal direction, counter-clockwise from +y.
std::vector<std::uint32_t> full_mesh_indices(int rows, int cols) {
  std::vector<std::uint32_t> idx;
  idx.reserve(static_cast<std::size_t>(rows - 1) * (cols - 1) * 6);
  for (int i = 0; i + 1 < rows; ++i)
    for (int j = 0; j + 1 < cols; ++j) {
      const auto a = static_cast<std::uint32_t>(i * cols + j), b = a + 1, c = a + static_cast<std::uint32_t>(cols),
                 d = c + 1;
      idx.insert(idx.end(), {a, c, b, b, c, d});
    }
  return idx;
}

gpu::Buffer device_buffer(const gpu::Context& ctx, std::span<const std::byte> bytes, vk::BufferUsageFlags usage,
                          const char* name) {
  gpu::Buffer b = gpu::create_buffer(ctx, std::max<std::size_t>(1, bytes.size()), usage | BU::eTransferDst,
                                     gpu::MemoryUse::device, name);
  gpu::upload(ctx, b, bytes);
  return b;
}

}  // namespace

void draw_range(const vk::raii::CommandBuffer& cmd, const view::IndexRange& r) {
  if (r.inside > 0) cmd.drawIndexed(r.inside, 1, r.first, 0, 0);
  if (r.across > 0) cmd.drawIndexed(r.across, 1, r.first + r.inside, 0, 0);
}

VisibleGeometry::CullSource VisibleGeometry::cull_source(const std::vector<view::LandVertex>& mesh, float y_sign) {
  CullSource c;
  for (const view::LandVertex& p : mesh) {
    c.x.push_back(p.position.x);
    c.y.push_back(y_sign * p.position.y);
    c.z.push_back(p.position.z);
    c.triangles.push_back(static_cast<std::uint32_t>(c.triangles.size()));
  }
  return c;
}

VisibleGeometry::VisibleGeometry(const gpu::Context& ctx, const sim::WaterModel& model)
    : ctx_(ctx), lod_(model.rows, model.cols) {
  const std::vector<view::LandVertex> mesh = view::build_land_mesh(model);
  land_source_ = cull_source(mesh, 1.0f);
  land_ = device_buffer(ctx, std::as_bytes(std::span(mesh)), BU::eVertexBuffer, "land vertices");
  const std::vector<view::LandVertex> above = view::mirrored_walls(mesh);
  mirrored_source_ = cull_source(above, -1.0f);
  mirrored_ = device_buffer(ctx, std::as_bytes(std::span(above)), BU::eVertexBuffer, "land walls above the water");
  const std::vector<view::LandVertex> below = view::submerged_walls(mesh, model);
  submerged_vertices_ = static_cast<std::uint32_t>(below.size());
  if (!below.empty())
    submerged_ = device_buffer(ctx, std::as_bytes(std::span(below)), BU::eVertexBuffer, "islands' walls under the water");
  submerged_boxes_ = view::touching_boxes(below);
  const std::vector<std::uint32_t> full = full_mesh_indices(model.rows, model.cols);
  full_index_count_ = static_cast<std::uint32_t>(full.size());
  full_indices_ = device_buffer(ctx, std::as_bytes(std::span(full)), BU::eIndexBuffer, "water full-mesh indices");
  lod_indices_.resize(lod_.max_indices());
}

// culled_'s index lists into `b` (host-visible), made larger first if they do not fit; the buffer
// must be idle.
void VisibleGeometry::write(gpu::Buffer& b, const char* what, std::uint32_t slot) const {
  const vk::DeviceSize bytes = std::max<std::size_t>(1, culled_.indices.size()) * sizeof(std::uint32_t);
  if (!*b.buffer || b.size < bytes)
    b = gpu::create_buffer(ctx_, std::max<vk::DeviceSize>(bytes, 2 * b.size), BU::eIndexBuffer, gpu::MemoryUse::upload,
                           std::string(what) + ", slot " + std::to_string(slot));
  std::memcpy(b.mapped, culled_.indices.data(), culled_.indices.size() * sizeof(std::uint32_t));
  b.flush(ctx_, bytes);
}

void VisibleGeometry::cull_land(std::uint32_t slot, const std::array<float, 16>& view_proj, int width, int height,
                                std::span<const view::PixelRect> rects, std::array<int, 2> mirror, VisibleDraws& out) {
  view::cull_triangles(land_source_.triangles, land_source_.positions(), view_proj, width, height, rects, culled_);
  write(slots_[slot].land, "land indices", slot);
  out.land_whole = culled_.whole;
  out.land_rects = culled_.rects;
  out.mirrored = {};
  if (mirror[0] > 0 && mirror[1] > 0) {
    view::cull_triangles(mirrored_source_.triangles, mirrored_source_.positions(), view_proj, mirror[0], mirror[1], {},
                         culled_);
    write(slots_[slot].mirrored, "mirrored walls' indices", slot);
    out.mirrored = culled_.whole;
  }
}

void VisibleGeometry::build_water(std::uint32_t slot, const lod::NodePositions& positions,
                                  std::span<const lod::TileBounds> tiles, const lod::Camera& camera,
                                  const std::array<float, 16>& view_proj, double tolerance_px,
                                  std::span<const view::PixelRect> rects, VisibleDraws& out) {
  out.water_rects.clear();
  out.full_mesh = full_mesh_ = tolerance_px <= 0;
  if (out.full_mesh) {  // the full mesh's buffer, drawn whole
    out.water_whole = {0, full_index_count_, 0};
    out.water_rects.assign(rects.size(), out.water_whole);
    out.water_triangles = full_index_count_ / 3;
    return;
  }
  lod_count_ = tiles.empty()
                   ? lod_.build(positions, camera, tolerance_px, lod_indices_)
                   : lod_.build(positions, lod::tile_ranges(tiles, positions.rows, positions.cols, positions.grid_spacing),
                                camera, tolerance_px, lod_indices_);
  view::cull_triangles(std::span(lod_indices_).first(lod_count_), {lod_.world_x(), lod_.world_y(), lod_.world_z()},
                       view_proj, camera.width, camera.height, rects, culled_);
  write(slots_[slot].water, "water LOD indices", slot);
  out.water_whole = culled_.whole;
  out.water_rects = culled_.rects;
  out.water_triangles = lod_count_ / 3;
}

void VisibleGeometry::bind_land(const vk::raii::CommandBuffer& cmd, std::uint32_t slot) const {
  cmd.bindVertexBuffers(0, *land_.buffer, vk::DeviceSize{0});
  cmd.bindIndexBuffer(*slots_[slot].land.buffer, 0, vk::IndexType::eUint32);
}

void VisibleGeometry::bind_mirrored(const vk::raii::CommandBuffer& cmd, std::uint32_t slot) const {
  cmd.bindVertexBuffers(0, *mirrored_.buffer, vk::DeviceSize{0});
  cmd.bindIndexBuffer(*slots_[slot].mirrored.buffer, 0, vk::IndexType::eUint32);
}

void VisibleGeometry::draw_submerged(const vk::raii::CommandBuffer& cmd) const {
  if (submerged_vertices_ == 0) return;
  cmd.bindVertexBuffers(0, *submerged_.buffer, vk::DeviceSize{0});
  cmd.draw(submerged_vertices_, 1, 0, 0);
}

void VisibleGeometry::bind_water(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, bool full_mesh) const {
  cmd.bindIndexBuffer(full_mesh ? *full_indices_.buffer : *slots_[slot].water.buffer, 0, vk::IndexType::eUint32);
}

}  // namespace pond::render
