#pragma once
// What every pass of one frame reads, set up once a frame by the frame loop: the frame's resources,
// the values its drawables get, its plan (which passes, which shadow rectangles), what of the pond
// it sees, and the pipelines and drawables.
#include <cstdint>
#include <span>

#include "render/frame_data.h"
#include "render/pass_drawable.h"
#include "render/pass_timestamps.h"
#include "render/visible_geometry.h"
#include "render/water_buffers.h"
#include "render/water_pipeline.h"
#include "view/frame_plan.h"

namespace pond::render {

struct FrameContext {
  std::uint32_t slot;
  FrameData& data;
  const WaterBuffers& water;  // what the water is drawn from this frame
  const Placeholders& placeholders;  // what a pass that is off binds in the water's set
  const view::FramePlan& plan;
  const VisibleDraws& draws;
  const VisibleGeometry& geometry;
  const WaterPipelines& pipes;
  std::span<PassDrawable* const> drawables;
  // The drawables' values for `cmd` (FrameInfo::cmd is ignored: each pass records into its own).
  FrameInfo info(const vk::raii::CommandBuffer& cmd) const;
  const FrameInfo& base;
  PassTimestamps& timestamps;  // written around each pass
};

inline FrameInfo FrameContext::info(const vk::raii::CommandBuffer& cmd) const {
  return {cmd, base.slot, base.view_proj, base.eye, base.extent, base.session, base.lighting, base.body_states, base.bodies,
          base.pixel_scale};
}

}  // namespace pond::render
