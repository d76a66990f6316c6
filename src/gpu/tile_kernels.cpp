#include "gpu/tile_kernels.h"

#include <string>

#include "gpu/shaders.h"
#include "gpu/water_layout.h"

namespace pond::gpu {
namespace {

using DT = vk::DescriptorType;
using BU = vk::BufferUsageFlagBits;

std::vector<DT> normals_tiles_bindings() {
  std::vector<DT> b(POND_NORMALS_TILES_BINDINGS, DT::eStorageBuffer);
  b[POND_NORMALS_BINDING_STATE] = DT::eUniformTexelBuffer;
  return b;
}
std::vector<DT> tiles_bindings() {
  std::vector<DT> b(POND_TILES_BINDINGS, DT::eStorageBuffer);
  b[POND_TILES_BINDING_COLUMNS] = DT::eUniformTexelBuffer;
  return b;
}

}  // namespace

TileKernels::TileKernels(const Context& ctx, const sim::WaterModel& model, const WaterKernels& water,
                         const Buffer& normals, bool denorm_preserve, std::uint32_t slots)
    : ctx_(ctx), water_(water), grid_(model.rows, model.cols) {
  const vk::DeviceSize bound_bytes = sizeof(TileBounds), column_bytes = POND_TILE_COLUMN_TEXELS * 4 * sizeof(float);
  columns_ = create_buffer(ctx_, grid_.tiles_y * static_cast<vk::DeviceSize>(model.cols) * column_bytes,
                           BU::eStorageBuffer | BU::eUniformTexelBuffer, MemoryUse::device, "tile columns");
  // Read by the merge through an RGBA32F view (fewer texels than the state's R32F view).
  columns_rgba_ = create_texel_view(ctx_, columns_, vk::Format::eR32G32B32A32Sfloat, "the tile columns");
  bounds_ = create_buffer(ctx_, grid_.tiles() * bound_bytes,
                          BU::eStorageBuffer | BU::eTransferSrc, MemoryUse::device, "tile bounds");
  if (host_readable_in_place(ctx_, bounds_)) {
    bounds_.mapped = bounds_.memory.mapMemory(0, VK_WHOLE_SIZE);
  } else {
    for (std::uint32_t k = 0; k < slots; ++k)
      host_.push_back(create_buffer(ctx_, bounds_.size, BU::eTransferDst, MemoryUse::readback,
                                    "tile bounds readback " + std::to_string(k)));
  }
  host_seen_.assign(slots, false);
  const SpecConstant local_x[] = {{POND_SPEC_NORMALS_LOCAL_X, water_.normals_local_x()}};
  normals_pipe_ = create_compute_pipeline(ctx_, water_normals_tiles_spirv(denorm_preserve), normals_tiles_bindings(),
                                          sizeof(NormalsPush), local_x, "water_normals (tile columns)");
  tiles_pipe_ = create_compute_pipeline(ctx_, water_tiles_spirv(denorm_preserve), tiles_bindings(),
                                        sizeof(TilesPush), {}, "water_tiles");

  // Two normals sets (the state's view; normals, columns) and the merge's (the columns' view; bounds).
  const vk::DescriptorPoolSize sizes[] = {{.type = DT::eUniformTexelBuffer, .descriptorCount = 2 + 1},
                                          {.type = DT::eStorageBuffer, .descriptorCount = 2 * 2 + 1}};
  pool_ = vk::raii::DescriptorPool(ctx_.device(),
                                   vk::DescriptorPoolCreateInfo{.flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                                .maxSets = 3, .poolSizeCount = 2, .pPoolSizes = sizes});
  const vk::DescriptorSetLayout layouts[] = {*normals_pipe_.set_layout, *normals_pipe_.set_layout,
                                             *tiles_pipe_.set_layout};
  vk::raii::DescriptorSets sets(ctx_.device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *pool_,
                                                                             .descriptorSetCount = 3,
                                                                             .pSetLayouts = layouts});
  tiles_set_ = std::move(sets[2]);
  normals_sets_.push_back(std::move(sets[0]));
  normals_sets_.push_back(std::move(sets[1]));

  const vk::DescriptorBufferInfo normals_info = normals.whole(), columns_info = columns_.whole(),
                                 bounds_info = bounds_.whole();
  for (int c = 0; c < 2; ++c) {
    const vk::BufferView view = *water_.state_r32()[c];
    const vk::WriteDescriptorSet writes[] = {
        {.dstSet = *normals_sets_[c], .dstBinding = POND_NORMALS_BINDING_STATE, .descriptorCount = 1,
         .descriptorType = DT::eUniformTexelBuffer, .pTexelBufferView = &view},
        {.dstSet = *normals_sets_[c], .dstBinding = POND_NORMALS_BINDING_NORMALS, .descriptorCount = 1,
         .descriptorType = DT::eStorageBuffer, .pBufferInfo = &normals_info},
        {.dstSet = *normals_sets_[c], .dstBinding = POND_NORMALS_BINDING_TILE_COLUMNS, .descriptorCount = 1,
         .descriptorType = DT::eStorageBuffer, .pBufferInfo = &columns_info}};
    ctx_.device().updateDescriptorSets(writes, nullptr);
  }
  const vk::BufferView columns_view = *columns_rgba_;
  const vk::WriteDescriptorSet writes[] = {
      {.dstSet = *tiles_set_, .dstBinding = POND_TILES_BINDING_COLUMNS, .descriptorCount = 1,
       .descriptorType = DT::eUniformTexelBuffer, .pTexelBufferView = &columns_view},
      {.dstSet = *tiles_set_, .dstBinding = POND_TILES_BINDING_BOUNDS, .descriptorCount = 1,
       .descriptorType = DT::eStorageBuffer, .pBufferInfo = &bounds_info}};
  ctx_.device().updateDescriptorSets(writes, nullptr);
}

void TileKernels::record(const vk::raii::CommandBuffer& cmd, int c, std::uint32_t slot) {
  water_.record_normals_with(cmd, normals_pipe_, normals_sets_[c]);  // its barrier after: columns readable
  const TilesPush push{.cols = static_cast<std::uint32_t>(grid_.cols), .tiles_x = static_cast<std::uint32_t>(grid_.tiles_x),
                       .tiles = static_cast<std::uint32_t>(grid_.tiles())};
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *tiles_pipe_.pipeline);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *tiles_pipe_.layout, 0, *tiles_set_, nullptr);
  cmd.pushConstants<TilesPush>(*tiles_pipe_.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
  cmd.dispatch(group_count(push.tiles, POND_TILES_LOCAL_X), 1, 1);
  host_seen_[slot] = false;  // a new copy
  if (host_.empty()) return;
  WaterKernels::record_barrier(cmd);
  cmd.copyBuffer(*bounds_.buffer, *host_[slot].buffer, vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = bounds_.size});
}

std::span<const TileBounds> TileKernels::host_bounds(std::uint32_t slot) {
  if (host_.empty()) return {static_cast<const TileBounds*>(bounds_.mapped), grid_.tiles()};
  if (!host_seen_[slot]) host_[slot].invalidate(ctx_);
  host_seen_[slot] = true;
  return {static_cast<const TileBounds*>(host_[slot].mapped), grid_.tiles()};
}

}  // namespace pond::gpu
