#include "render/caustics_pass.h"

#include <string>

#include "render/barrier_batch.h"
#include "render/reflection_pass.h"
#include "render/render_shaders.h"
#include "view/sun_shadow.h"

namespace pond::render {
namespace {

// Until a slot's map is written its binding holds the frame's placeholder (FrameRing::placeholders),
// the reflection's format.
static_assert(kCausticsFormat == kReflectionFormat);

using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
using L = vk::ImageLayout;
namespace cs = shared::caustics;

constexpr vk::DescriptorType kBindings[] = {vk::DescriptorType::eUniformTexelBuffer,
                                            vk::DescriptorType::eUniformTexelBuffer, vk::DescriptorType::eStorageImage};
static_assert(std::size(kBindings) == POND_CAUSTICS_BINDINGS && POND_CAUSTICS_BINDING_STATE == 0 &&
              POND_CAUSTICS_BINDING_NORMALS == 1 && POND_CAUSTICS_BINDING_MAP == 2);

}  // namespace

CausticsPass::CausticsPass(const gpu::Context& ctx, const sim::WaterModel& model, std::uint32_t slots)
    : ctx_(ctx), slot_count_(slots), sampler_(create_reflection_sampler(ctx)) {
  const view::GridSize size = view::caustics_extent(model.rows, model.cols);
  extent_ = vk::Extent2D{size.width, size.height};
}

void CausticsPass::make() {
  const gpu::Context& ctx = ctx_;
  const std::uint32_t slots = slot_count_;
  pipeline_ = gpu::create_compute_pipeline(ctx, caustics_comp_spirv(), kBindings, sizeof(CausticsPush), {}, "caustics");
  const vk::DescriptorPoolSize sizes[] = {{.type = vk::DescriptorType::eUniformTexelBuffer, .descriptorCount = 2 * slots},
                                          {.type = vk::DescriptorType::eStorageImage, .descriptorCount = slots}};
  pool_ = vk::raii::DescriptorPool(ctx.device(), vk::DescriptorPoolCreateInfo{
                                                     .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                     .maxSets = slots, .poolSizeCount = 2, .pPoolSizes = sizes});
  using U = vk::ImageUsageFlagBits;
  for (std::uint32_t k = 0; k < slots; ++k) {
    Slot s;
    const std::string n = ", slot " + std::to_string(k);
    s.map = create_image(ctx, extent_, kCausticsFormat, U::eStorage | U::eSampled | U::eTransferSrc,
                         vk::ImageAspectFlagBits::eColor, "caustics map" + n);
    const vk::DescriptorSetLayout layout = *pipeline_.set_layout;
    s.set = std::move(vk::raii::DescriptorSets(ctx.device(), vk::DescriptorSetAllocateInfo{
                                                                 .descriptorPool = *pool_, .descriptorSetCount = 1,
                                                                 .pSetLayouts = &layout})[0]);
    slots_.push_back(std::move(s));
  }
  // No wait here: a map is first written by its slot's first frame with caustics, before that frame
  // samples it (bind_water binds the placeholder until then).
}

vk::BufferView CausticsPass::view_of(Slot& slot, const gpu::Buffer& buffer, vk::Format format) {
  for (const auto& [b, view] : slot.views)
    if (b == *buffer.buffer) return *view;
  slot.views.emplace_back(*buffer.buffer, gpu::create_texel_view(ctx_, buffer, format, "the caustics pass"));
  return *slot.views.back().second;
}

void CausticsPass::water_bindings(std::vector<vk::DescriptorSetLayoutBinding>& out) const {
  out.push_back({.binding = POND_CAUSTICS_WATER_BINDING, .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                 .descriptorCount = 1, .stageFlags = vk::ShaderStageFlagBits::eFragment});
}

void CausticsPass::prepare(const FrameContext& frame) {
  if (enabled(frame) && !made()) make();
  if (!made()) return;
  Slot& s = slots_[frame.slot];
  const std::uint64_t generation = frame.base.session.solver_generation();
  if (s.generation != generation) s.views.clear();  // of a replaced solver's buffers; the slot is finished
  s.generation = generation;
  if (enabled(frame)) bind(frame.slot, *frame.water.state, *frame.water.normals);
}

void CausticsPass::bind_water(const FrameContext& frame, WaterSetWrites& set, WaterFrame& /*uniforms*/) {
  // The slot's map where this frame writes it or an earlier one did (it then rests in shader-read);
  // else no pipeline of the frame samples it, and the placeholder (as readable) stands in.
  const bool map = made() && (enabled(frame) || slots_[frame.slot].written);
  const vk::ImageView view = map ? *slots_[frame.slot].map.view : *frame.placeholders.reflection.view;
  set.image(POND_CAUSTICS_WATER_BINDING, *sampler_, view, L::eShaderReadOnlyOptimal);
}

void CausticsPass::declare(const FrameContext& frame, PassDeclaration& d) {
  d.writes.push_back({.image = *slots_[frame.slot].map.image, .layout = L::eGeneral, .stages = S::eComputeShader,
                      .access = A::eShaderStorageWrite});
}

void CausticsPass::record(const vk::raii::CommandBuffer& cmd, const FrameContext& frame) {
  slots_[frame.slot].written = true;
  const sim::WaterModel& model = frame.base.session.model();
  record_dispatch(cmd, frame.slot,
                  view::caustics_push(model, view::unit(frame.base.lighting.sun), model.basin.floor_depth,
                                      frame.water.stride, frame.water.pitch));
}

void CausticsPass::bind(std::uint32_t slot, const gpu::Buffer& state, const gpu::Buffer& normals) {
  if (!made()) make();
  Slot& s = slots_[slot];
  const vk::BufferView views[] = {view_of(s, state, vk::Format::eR32Sfloat),
                                  view_of(s, normals, vk::Format::eR32G32B32A32Sfloat)};
  const vk::DescriptorImageInfo map{.imageView = *s.map.view, .imageLayout = L::eGeneral};
  using DT = vk::DescriptorType;
  const vk::WriteDescriptorSet writes[] = {
      {.dstSet = *s.set, .dstBinding = POND_CAUSTICS_BINDING_STATE, .descriptorCount = 1,
       .descriptorType = DT::eUniformTexelBuffer, .pTexelBufferView = &views[0]},
      {.dstSet = *s.set, .dstBinding = POND_CAUSTICS_BINDING_NORMALS, .descriptorCount = 1,
       .descriptorType = DT::eUniformTexelBuffer, .pTexelBufferView = &views[1]},
      {.dstSet = *s.set, .dstBinding = POND_CAUSTICS_BINDING_MAP, .descriptorCount = 1,
       .descriptorType = DT::eStorageImage, .pImageInfo = &map}};
  ctx_.device().updateDescriptorSets(writes, nullptr);
}

void CausticsPass::record_dispatch(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, const CausticsPush& push) const {
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipeline_.layout, 0, *slots_[slot].set, nullptr);
  cmd.pushConstants<CausticsPush>(*pipeline_.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline_.pipeline);
  cmd.dispatch(gpu::group_count(push.map.x, POND_CAUSTICS_LOCAL), gpu::group_count(push.map.y, POND_CAUSTICS_LOCAL), 1);
}

void CausticsPass::record(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, const CausticsPush& push) {
  slots_[slot].written = true;
  // The map from the water's sampling (or creation) to the compute write (its contents all
  // rewritten), and back.
  const vk::Image map = *slots_[slot].map.image;
  const vk::ImageMemoryBarrier2 to_write = image_barrier(map, vk::ImageAspectFlagBits::eColor, L::eUndefined, L::eGeneral,
                                                         S::eFragmentShader, {}, S::eComputeShader, A::eShaderStorageWrite);
  const vk::ImageMemoryBarrier2 to_read =
      image_barrier(map, vk::ImageAspectFlagBits::eColor, L::eGeneral, L::eShaderReadOnlyOptimal, S::eComputeShader,
                    A::eShaderStorageWrite, S::eFragmentShader, A::eShaderSampledRead);
  cmd.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &to_write});
  record_dispatch(cmd, slot, push);
  cmd.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &to_read});
}

std::vector<float> CausticsPass::read_map(std::uint32_t slot) {
  const Slot& s = slots_[slot];
  const vk::Extent2D e = s.map.extent;
  const vk::DeviceSize bytes = vk::DeviceSize{e.width} * e.height * 4;
  const gpu::Buffer readback = gpu::create_buffer(ctx_, bytes, vk::BufferUsageFlagBits::eTransferDst,
                                                  gpu::MemoryUse::readback, "caustics map readback");
  ctx_.device().waitIdle();
  ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    const auto to_copy = image_barrier(*s.map.image, vk::ImageAspectFlagBits::eColor, L::eShaderReadOnlyOptimal, L::eTransferSrcOptimal, S::eAllCommands,
                                     A::eShaderStorageWrite, S::eCopy, A::eTransferRead);
    cmd.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &to_copy});
    cmd.copyImageToBuffer(*s.map.image, L::eTransferSrcOptimal, *readback.buffer,
                          vk::BufferImageCopy{.imageSubresource = {.aspectMask = vk::ImageAspectFlagBits::eColor,
                                                                   .mipLevel = 0, .baseArrayLayer = 0, .layerCount = 1},
                                              .imageExtent = {e.width, e.height, 1}});
    const auto back = image_barrier(*s.map.image, vk::ImageAspectFlagBits::eColor, L::eTransferSrcOptimal, L::eShaderReadOnlyOptimal, S::eCopy, {},
                                  S::eFragmentShader, A::eShaderSampledRead);
    const vk::BufferMemoryBarrier2 to_host{.srcStageMask = S::eCopy, .srcAccessMask = A::eTransferWrite,
                                           .dstStageMask = S::eHost, .dstAccessMask = A::eHostRead,
                                           .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                           .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                           .buffer = *readback.buffer, .offset = 0, .size = VK_WHOLE_SIZE};
    cmd.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &to_host,
                                            .imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &back});
  });
  readback.invalidate(ctx_);
  std::vector<float> out(static_cast<std::size_t>(e.width) * e.height);
  const auto* rgba = static_cast<const std::uint8_t*>(readback.mapped);
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = static_cast<float>(rgba[4 * k]) / 255.0f * cs::kCausticsDecode;
  return out;
}

}  // namespace pond::render
