#pragma once
// What of the pond a frame sees: the land (built once from the model), the water's triangles (the
// view-dependent LOD of the frame's positions, or the full mesh) and the mirrored walls the
// reflection draws, each culled to the frame's view and its shadow rectangles
// (view/triangle_cull.h) and streamed into the frame slot's host-visible index buffers; and the
// islands' walls under the water (render/submerged_pass.h), drawn whole.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "gpu/buffer.h"
#include "lod/camera_budget.h"
#include "lod/lod_builder.h"
#include "lod/node_positions.h"
#include "render/frame_constants.h"
#include "sim/model.h"
#include "view/land_mesh.h"
#include "view/pixel_rect.h"
#include "view/sun_shadow.h"
#include "view/triangle_cull.h"

namespace pond::render {

// What the main pass and the reflection draw of the frame's index buffers.
struct VisibleDraws {
  view::IndexRange land_whole, water_whole, mirrored;
  std::vector<view::IndexRange> land_rects, water_rects;  // per shadow rectangle
  bool full_mesh = false;                                 // the water from the full mesh's indices
  std::size_t water_triangles = 0;                        // before culling
};

// One draw list of a culled mesh: the triangles inside the view volume, then those across its
// boundary, from the bound index buffer.
void draw_range(const vk::raii::CommandBuffer& cmd, const view::IndexRange& range);

class VisibleGeometry {
 public:
  // The land of `model`'s node kinds and basin.
  VisibleGeometry(const gpu::Context& ctx, const sim::WaterModel& model);

  // The land's triangles for the view (and its shadow rectangles), and with `mirror` (the
  // reflection's size; 0 x 0: none) the mirrored walls', into slot's index buffers (finished).
  void cull_land(std::uint32_t slot, const std::array<float, 16>& view_proj, int width, int height,
                 std::span<const view::PixelRect> rects, std::array<int, 2> mirror, VisibleDraws& out);
  // The water's: the LOD of `positions` within `tolerance_px` (0: the full mesh), culled likewise.
  // `tiles`: the positions' tile bounds from the solver (empty: the builder computes its ranges from
  // the positions, reading every node).
  void build_water(std::uint32_t slot, const lod::NodePositions& positions, std::span<const lod::TileBounds> tiles,
                   const lod::Camera& camera, const std::array<float, 16>& view_proj, double tolerance_px,
                   std::span<const view::PixelRect> rects, VisibleDraws& out);

  // Bind the vertex and index buffers of the land, the mirrored walls, the water (slot's).
  void bind_land(const vk::raii::CommandBuffer& cmd, std::uint32_t slot) const;
  void bind_mirrored(const vk::raii::CommandBuffer& cmd, std::uint32_t slot) const;
  void bind_water(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, bool full_mesh) const;
  // Binds and draws the islands' walls under the water (view::submerged_walls), all of them: few
  // triangles, clipped by the device.
  void draw_submerged(const vk::raii::CommandBuffer& cmd) const;
  // Their boxes, one per island (for view::plan_frame).
  std::span<const view::ShadowCaster> submerged_boxes() const { return submerged_boxes_; }

  std::size_t land_triangles() const { return land_source_.triangles.size() / 3; }
  std::size_t full_triangles() const { return full_index_count_ / 3; }
  // The nodes the last LOD read (lod/lod_builder.h: reads()); none for the full mesh.
  std::optional<std::vector<core::GridWindow>> lod_reads() const {
    return full_mesh_ ? std::optional(std::vector<core::GridWindow>{}) : lod_.reads();
  }
  // The LOD's last triangles before culling (node indices), for tests and tools.
  std::span<const std::uint32_t> lod_triangles() const { return std::span(lod_indices_).first(lod_count_); }

 private:
  // A non-indexed triangle list's vertices, structure of arrays, and its triangles (0, 1, 2, ...).
  struct CullSource {
    std::vector<float> x, y, z;
    std::vector<std::uint32_t> triangles;
    view::MeshPositions positions() const { return {x, y, z}; }
  };
  static CullSource cull_source(const std::vector<view::LandVertex>& mesh, float y_sign);
  void write(gpu::Buffer& b, const char* what, std::uint32_t slot) const;  // culled_ into b

  const gpu::Context& ctx_;
  gpu::Buffer land_, mirrored_, submerged_, full_indices_;
  std::uint32_t full_index_count_ = 0, submerged_vertices_ = 0;
  std::vector<view::ShadowCaster> submerged_boxes_;
  CullSource land_source_, mirrored_source_;  // the mirrored walls' with y negated, as land.vert mirrors
  lod::LodBuilder lod_;
  std::vector<std::uint32_t> lod_indices_;
  std::size_t lod_count_ = 0;
  bool full_mesh_ = false;  // the last build_water() drew the full mesh
  view::CulledMesh culled_;  // scratch
  struct SlotIndices {
    gpu::Buffer water, land, mirrored;
  };
  std::array<SlotIndices, kFramesInFlight> slots_;
};

}  // namespace pond::render
