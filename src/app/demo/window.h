#pragma once
// The demo's GLFW window: the library session (which is also the "is there a display?" check), one
// resizable window without a client API (Vulkan draws into it), and its input as InputEvents.
#include <string>
#include <vector>

#include "app/demo/input_event.h"
#include "gpu/vulkan.h"

struct GLFWwindow;

namespace pond::app::demo {

// glfwInit / glfwTerminate. Throws RuntimeError with the headless hint when there is no display.
class GlfwSession {
 public:
  GlfwSession();
  ~GlfwSession();
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;
};

// The message for a machine without a display: says how to render headless instead.
std::string no_display_message(const std::string& why);

class Window {
 public:
  Window(int width, int height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close() const;
  // Polls the window system; the events since the last poll are appended to `events()`.
  void poll();
  // Blocks until something happens (while minimized), at most `seconds`.
  void wait(double seconds);
  std::vector<InputEvent>& events() { return events_; }
  // The framebuffer size in pixels (0 x 0 while minimized on some systems; X11 keeps the size),
  // as GLFW last reported it (polled once at creation, then from its callback): asking the window
  // system every frame would be a round trip, which on X waits for the server to finish the
  // previous frame's image.
  vk::Extent2D framebuffer_extent() const { return framebuffer_; }
  // Iconified (GLFW's callback, likewise), or with an empty framebuffer: nothing to draw into,
  // nothing anyone sees.
  bool minimized() const { return iconified_ || framebuffer_.width == 0 || framebuffer_.height == 0; }
  void minimize() const;  // a request to the window manager (none: nothing happens)
  void restore() const;
  void set_size(int width, int height) const;
  void set_title(const std::string& title) const;
  double cursor_x() const { return cursor_x_; }
  double cursor_y() const { return cursor_y_; }

  // For the Vulkan context: the instance extensions a surface needs, and the surface.
  static std::vector<std::string> required_instance_extensions();
  VkSurfaceKHR create_surface(VkInstance instance) const;

 private:
  static Window& self(GLFWwindow* w);
  GLFWwindow* window_ = nullptr;
  std::vector<InputEvent> events_;
  double cursor_x_ = 0, cursor_y_ = 0;
  vk::Extent2D framebuffer_;
  bool iconified_ = false;
};

}  // namespace pond::app::demo
