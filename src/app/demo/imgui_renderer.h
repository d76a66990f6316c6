#pragma once
// Draws ImGui's draw data inside the frame loop's pass, as a PassDrawable's occluding overlay: before
// the scene, at the nearest depth, so the scene behind the panel is never shaded (the demo makes
// ImGui's windows opaque for it, demo_app.cpp).
// Written here rather than taken from libimgui's Vulkan backend because that backend (1.86) needs
// a VkRenderPass (the frame loop uses dynamic rendering) and links the Vulkan loader directly
// (pond loads it at run time, gpu/vulkan.h).
//
// Vertex and index buffers are per frame slot, host-visible, and only grow (doubling), so a frame
// allocates nothing once the UI's size has settled. The font atlas is uploaded once.
#include <array>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "render/frame_constants.h"
#include "render/pass_drawable.h"
#include "render/render_target.h"

namespace pond::app::demo {

class ImGuiRenderer final : public render::PassDrawable {
 public:
  // Needs a current ImGui context (it uploads the context's font atlas).
  ImGuiRenderer(const gpu::Context& ctx, vk::Format color_format);

  void draw(const render::FrameInfo&) override {}
  // Copies ImGui::GetDrawData() into the slot's buffers and draws it. Not in prepare(): the demo
  // may build its panel again between the frame's halves (after a failed acquire).
  void draw_occluding(const render::FrameInfo& frame) override;

 private:
  struct SlotBuffers {
    gpu::Buffer vertices, indices;
    bool ready = false;  // this slot holds this frame's data
  };
  void grow(gpu::Buffer& buffer, vk::DeviceSize bytes, vk::BufferUsageFlags usage, const char* name);
  void upload(const render::FrameInfo& frame);  // ImGui::GetDrawData() into the slot's buffers

  const gpu::Context& ctx_;
  bool srgb_target_ = false;
  render::Image font_;
  vk::raii::Sampler sampler_ = nullptr;
  vk::raii::DescriptorSetLayout set_layout_ = nullptr;
  vk::raii::DescriptorPool pool_ = nullptr;
  vk::raii::DescriptorSet set_ = nullptr;
  vk::raii::PipelineLayout layout_ = nullptr;
  vk::raii::Pipeline pipeline_ = nullptr;
  std::array<SlotBuffers, render::kFramesInFlight> slots_;
};

}  // namespace pond::app::demo
