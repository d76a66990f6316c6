#include "app/demo/window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // after gpu/vulkan.h: declares glfwCreateWindowSurface

#include <cstdlib>

#include "core/errors.h"

namespace pond::app::demo {
namespace {

std::string last_glfw_error() {
  const char* text = nullptr;
  glfwGetError(&text);
  return text ? text : "unknown GLFW error";
}

vk::Extent2D extent(int width, int height) {
  return {static_cast<std::uint32_t>(width < 0 ? 0 : width), static_cast<std::uint32_t>(height < 0 ? 0 : height)};
}

}  // namespace

std::string no_display_message(const std::string& why) {
  return "the demo needs a display (" + why +
         "); render headless instead: pond render --steps 200 --size 1280x720 --out frame.png";
}

GlfwSession::GlfwSession() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!x11 || !*x11) && (!wayland || !*wayland))
    throw RuntimeError(no_display_message("no DISPLAY or WAYLAND_DISPLAY is set"));
  if (glfwInit() != GLFW_TRUE) throw RuntimeError(no_display_message("GLFW cannot open it: " + last_glfw_error()));
  if (glfwVulkanSupported() != GLFW_TRUE) {
    glfwTerminate();
    throw RuntimeError("GLFW finds no Vulkan loader for the window; render headless instead: pond render --steps 200 --size 1280x720 --out frame.png");
  }
}

GlfwSession::~GlfwSession() { glfwTerminate(); }

Window& Window::self(GLFWwindow* w) { return *static_cast<Window*>(glfwGetWindowUserPointer(w)); }

Window::Window(int width, int height, const std::string& title) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) throw RuntimeError("cannot create the demo window: " + last_glfw_error());
  events_.reserve(256);
  glfwSetWindowUserPointer(window_, this);
  // Callbacks only record; controls.cpp decides what an event means. ImGui's GLFW backend is
  // installed after these and chains to them.
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
    self(w).events_.push_back({.kind = InputEvent::Kind::key, .code = key, .action = action, .mods = mods});
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int mods) {
    Window& me = self(w);
    me.events_.push_back({.kind = InputEvent::Kind::button, .code = button, .action = action, .mods = mods,
                          .x = me.cursor_x_, .y = me.cursor_y_});
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    Window& me = self(w);
    me.cursor_x_ = x, me.cursor_y_ = y;
    me.events_.push_back({.kind = InputEvent::Kind::cursor, .x = x, .y = y});
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double dx, double dy) {
    self(w).events_.push_back({.kind = InputEvent::Kind::scroll, .x = dx, .y = dy});
  });
  glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int fw, int fh) {
    Window& me = self(w);
    me.framebuffer_ = extent(fw, fh);
    me.events_.push_back({.kind = InputEvent::Kind::resize, .x = static_cast<double>(fw), .y = static_cast<double>(fh)});
  });
  glfwSetWindowIconifyCallback(window_, [](GLFWwindow* w, int iconified) { self(w).iconified_ = iconified == GLFW_TRUE; });
  int fw = 0, fh = 0;
  glfwGetFramebufferSize(window_, &fw, &fh);
  framebuffer_ = extent(fw, fh);
  iconified_ = glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE;
}

Window::~Window() { glfwDestroyWindow(window_); }

bool Window::should_close() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void Window::request_close() const { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::poll() { glfwPollEvents(); }
void Window::wait(double seconds) { glfwWaitEventsTimeout(seconds); }

void Window::minimize() const { glfwIconifyWindow(window_); }
void Window::restore() const { glfwRestoreWindow(window_); }

void Window::set_size(int width, int height) const { glfwSetWindowSize(window_, width, height); }
void Window::set_title(const std::string& title) const { glfwSetWindowTitle(window_, title.c_str()); }

std::vector<std::string> Window::required_instance_extensions() {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw RuntimeError("GLFW cannot make Vulkan surfaces on this display: " + last_glfw_error());
  return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR Window::create_surface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  if (glfwCreateWindowSurface(instance, window_, nullptr, &surface) != VK_SUCCESS)
    throw RuntimeError("cannot create a Vulkan surface for the window: " + last_glfw_error());
  return surface;
}

}  // namespace pond::app::demo
