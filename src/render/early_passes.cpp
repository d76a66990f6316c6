#include "render/early_passes.h"

#include "render/barrier_batch.h"
#include "render/shadow_pass.h"
#include "render/submerged_pass.h"

namespace pond::render {
namespace {
using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
}  // namespace

void record_early_passes(const vk::raii::CommandBuffer& cmd, const FrameContext& frame, const CausticsPass& caustics,
                         const shared::caustics::CausticsPush& caustics_push) {
  FrameData& d = frame.data;
  const view::FramePlan& plan = frame.plan;
  const FrameInfo info = frame.info(cmd);
  // Before: the solver's writes (compute, and transfers of uploads) -> the vertex shader (this
  // pass's and the main one's, later in submission order) and the caustics' reads; each image to
  // the layout it is written in.
  BarrierBatch batch;
  batch.memory.push_back({.srcStageMask = S::eComputeShader | S::eTransfer,
                          .srcAccessMask = A::eShaderWrite | A::eTransferWrite,
                          .dstStageMask = S::eVertexShader | S::eVertexAttributeInput | S::eComputeShader,
                          .dstAccessMask = A::eShaderRead | A::eVertexAttributeRead});
  if (plan.caustics) batch.images.push_back(caustics.begin_barrier(frame.slot));
  if (plan.shadow) batch.images.push_back(shadow_pass_begin(d.shadow));
  if (plan.reflection)
    for (const vk::ImageMemoryBarrier2& b : layer_pass_begin(d.reflection)) batch.images.push_back(b);
  if (plan.submerged)
    for (const vk::ImageMemoryBarrier2& b : layer_pass_begin(d.submerged)) batch.images.push_back(b);
  batch.record(cmd);

  if (plan.caustics) {
    const PassTimestamps::Scope timed = frame.timestamps.scope(cmd, frame.slot, TimedPass::caustics);
    caustics.record_dispatch(cmd, frame.slot, caustics_push);
  }
  if (plan.shadow) {
    const PassTimestamps::Scope timed = frame.timestamps.scope(cmd, frame.slot, TimedPass::shadow);
    FrameInfo sun = info;
    sun.view_proj = plan.shadow->clip.data();
    sun.extent = d.shadow.extent;
    record_shadow_pass(cmd, d.shadow, [&] {
      for (PassDrawable* p : frame.drawables) p->draw_shadow(sun);
    });
  }
  if (plan.reflection) {
    const PassTimestamps::Scope timed = frame.timestamps.scope(cmd, frame.slot, TimedPass::reflection);
    FrameInfo mirrored = info;
    mirrored.extent = d.reflection.color.extent;
    mirrored.pixel_scale = static_cast<float>(mirrored.extent.height) / static_cast<float>(info.extent.height);
    record_layer_pass(cmd, d.reflection, [&] {
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *frame.pipes.layout, 0, *d.set, nullptr);
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *frame.pipes.land_mirror);
      frame.geometry.bind_mirrored(cmd, frame.slot);
      draw_range(cmd, frame.draws.mirrored);
      for (PassDrawable* p : frame.drawables) p->draw_reflected(mirrored);
    });
  }
  if (plan.submerged) {
    const PassTimestamps::Scope timed = frame.timestamps.scope(cmd, frame.slot, TimedPass::submerged);
    record_layer_pass(cmd, d.submerged, [&] {
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *frame.pipes.layout, 0, *d.set, nullptr);
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *frame.pipes.land_submerged);
      frame.geometry.draw_submerged(cmd);
      for (PassDrawable* p : frame.drawables) p->draw_submerged(info);
    });
  }
  // After: what they wrote to shader-read for the main pass's fragment shaders (a frame without
  // shadows or without the submerged layer still puts the map or the layer, which every water.frag
  // declares, in that layout).
  if (plan.caustics) batch.images.push_back(caustics.end_barrier(frame.slot));
  batch.images.push_back(plan.shadow ? shadow_pass_end(d.shadow) : shadow_map_unused(d.shadow));
  if (plan.reflection) batch.images.push_back(layer_pass_end(d.reflection));  // read only by water_reflect.frag
  batch.images.push_back(plan.submerged ? layer_pass_end(d.submerged) : layer_unused(d.submerged));
  batch.record(cmd);
}

}  // namespace pond::render
