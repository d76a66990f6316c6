#pragma once
// The frame's passes before the main one, in recording order: the caustics' and the foam's compute
// passes (render/caustics_pass.h, render/foam_pass.h), the sun's shadow map
// (render/shadow_pass.h), the planar reflection (render/reflection_pass.h) and the submerged layer
// (render/submerged_pass.h), each a FramePass (render/frame_pass.h) recorded when the frame's plan
// has it, with the barriers their declarations call for. None reads what another writes, so their
// barriers go in two batches: one before them all (with the compute -> vertex dependency on the
// water's state and normals), one after.
#include "render/caustics_pass.h"
#include "render/foam_pass.h"
#include "render/frame_context.h"
#include "shared/caustics.h"

namespace pond::render {

// Returns which passes it recorded.
PassSet record_early_passes(const vk::raii::CommandBuffer& cmd, const FrameContext& frame, const CausticsPass& caustics,
                            FoamPass& foam, const shared::caustics::CausticsPush& caustics_push);

}  // namespace pond::render
