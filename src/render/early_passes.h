#pragma once
// The passes before the main one, recorded into one command buffer: the caustics' compute pass
// (render/caustics_pass.h), the sun's shadow map (render/shadow_pass.h) and the planar reflection
// (render/reflection_pass.h), each when the frame's plan has it. None reads what another writes,
// so their barriers go in two batches (render/barrier_batch.h): one before them all (with the
// compute -> vertex dependency on the water's state and normals), one after.
#include "render/caustics_pass.h"
#include "render/frame_context.h"
#include "shared/caustics.h"

namespace pond::render {

void record_early_passes(const vk::raii::CommandBuffer& cmd, const FrameContext& frame, const CausticsPass& caustics,
                         const shared::caustics::CausticsPush& caustics_push);

}  // namespace pond::render
