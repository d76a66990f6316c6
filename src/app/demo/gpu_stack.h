#pragma once
// Everything the demo has on its Vulkan device, in dependency order (destroyed bottom-up): the
// context (instance, the window's surface, the device), the swapchain, the UI's and the
// screenshots' resources, and where the session's GPU solvers come from. Made again, whole, when
// the device is lost (device_recovery.cpp); the frame loop and its drawables are made on top of it.
#include <functional>

#include "app/demo/demo_app.h"
#include "app/demo/imgui_renderer.h"
#include "app/demo/screenshot.h"
#include "app/demo/swapchain.h"
#include "app/demo/window.h"
#include "gpu/context.h"
#include "gpu/gpu_solvers.h"

namespace pond::app::demo {

// The swapchain's first extent, asked of the new context (the demo refuses sizes it cannot draw).
using FirstExtent = std::function<vk::Extent2D(const gpu::Context&)>;

struct GpuStack {
  GpuStack(const DemoOptions& options, const Window& window, bool vsync, const FirstExtent& extent)
      : ctx(gpu::ContextOptions{.device = options.device, .validation = options.validation}, surface_of(window)),
        swapchain(ctx, extent(ctx), vsync),
        imgui(ctx, swapchain.format()),
        shots(ctx),
        solvers(ctx) {}
  GpuStack(const GpuStack&) = delete;
  GpuStack& operator=(const GpuStack&) = delete;
  ~GpuStack() { ctx.wait_idle_for_teardown(); }  // nothing the GPU may still use goes before it is idle

  gpu::Context ctx;
  Swapchain swapchain;
  ImGuiRenderer imgui;
  ScreenshotWriter shots;
  gpu::GpuSolvers solvers;

 private:
  static gpu::WindowSurface surface_of(const Window& window) {
    return gpu::WindowSurface{.instance_extensions = Window::required_instance_extensions(),
                              .make_surface = [&window](VkInstance instance) { return window.create_surface(instance); }};
  }
};

}  // namespace pond::app::demo
