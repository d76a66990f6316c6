#pragma once
// The Vulkan context of pond: instance (with the validation layer, synchronization validation and
// a debug-utils messenger when asked), the chosen device, one compute queue and a command pool.
// Headless: no surface or swapchain extension is required; a window adds those later.
//
// Members are vk::raii objects declared in dependency order, so they are destroyed in reverse
// (pool, device, messenger, instance) and nothing is destroyed by hand.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "gpu/validation_log.h"
#include "gpu/vulkan.h"

namespace pond::gpu {

struct ContextOptions {
  std::string device;       // substring of the device name; empty = the most capable
  bool validation = false;  // VK_LAYER_KHRONOS_validation + synchronization validation + messenger
};

class Context {
 public:
  // Throws RuntimeError when Vulkan, the validation layer (if asked) or a device is missing.
  explicit Context(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const vk::raii::Device& device() const { return device_; }
  const vk::raii::PhysicalDevice& physical() const { return physical_; }
  const vk::raii::Queue& queue() const { return queue_; }
  std::uint32_t queue_family() const { return family_; }
  const std::string& device_name() const { return device_name_; }
  // Validation messages so far (empty without validation).
  const ValidationLog& validation_log() const { return *log_; }

  // Records commands into a fresh primary command buffer, submits it and waits for it.
  void submit_and_wait(const std::function<void(const vk::raii::CommandBuffer&)>& record) const;

  // Gives a Vulkan object a name in validation messages and debuggers (no-op without debug utils).
  template <class Raii>
  void name(const Raii& object, const std::string& text) const {
    set_name(Raii::objectType, reinterpret_cast<std::uint64_t>(static_cast<typename Raii::CType>(*object)), text);
  }

 private:
  void set_name(vk::ObjectType type, std::uint64_t handle, const std::string& text) const;

  std::unique_ptr<ValidationLog> log_;  // first: the messenger's user data outlives the messenger
  bool debug_utils_ = false;
  vk::raii::Context loader_;
  vk::raii::Instance instance_ = nullptr;
  std::optional<vk::raii::DebugUtilsMessengerEXT> messenger_;
  vk::raii::PhysicalDevice physical_ = nullptr;
  std::uint32_t family_ = 0;
  std::string device_name_;
  vk::raii::Device device_ = nullptr;
  vk::raii::Queue queue_ = nullptr;
  vk::raii::CommandPool pool_ = nullptr;
};

}  // namespace pond::gpu
