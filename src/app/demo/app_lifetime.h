#pragma once
// Two lifetime guards of the demo app: ImGui's context with its GLFW backend, and the wait for an
// idle GPU before anything the GPU may still use is destroyed.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include "gpu/context.h"

namespace pond::app::demo {

// ImGui's context and its GLFW backend (installed after the window's callbacks, which it chains).
class ImGuiSession {
 public:
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // nothing written to the working directory
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.AntiAliasedLinesUseTex = false;  // the atlas is sampled nearest (imgui_renderer.cpp)
    // Opaque windows: the UI is drawn before the scene and hides what is behind it by depth
    // (imgui_renderer.h), so a see-through window would show the clear colour, not the water.
    style.Colors[ImGuiCol_WindowBg].w = 1.0f;
    style.Colors[ImGuiCol_PopupBg].w = 1.0f;
    ImGui_ImplGlfw_InitForVulkan(window, true);
  }
  ~ImGuiSession() {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// Last member of the app: on any exit (also by exception) the GPU is idle before anything it may
// still use is destroyed.
struct IdleBeforeTeardown {
  const gpu::Context& ctx;
  ~IdleBeforeTeardown() { ctx.wait_idle_for_teardown(); }
};

}  // namespace pond::app::demo
