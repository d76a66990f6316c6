#pragma once
// A lifetime guard of the demo app: ImGui's context with its GLFW backend.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

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

}  // namespace pond::app::demo
