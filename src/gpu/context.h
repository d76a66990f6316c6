#pragma once
// The Vulkan context of pond: instance (with the validation layer, synchronization validation and
// a debug-utils messenger when asked), the chosen device, one compute queue and a command pool.
// Headless by default; with a WindowSurface (the windowed demo) it also owns the
// window's surface, enables VK_KHR_swapchain and picks a queue family that can present to it.
//
// Members are vk::raii objects declared in dependency order, so they are destroyed in reverse
// (pool, device, messenger, instance) and nothing is destroyed by hand.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gpu/validation_log.h"
#include "gpu/vulkan.h"

namespace pond::gpu {

struct ContextOptions {
  std::string device;       // substring of the device name; empty = $POND_DEVICE, else the most capable
  bool validation = false;  // VK_LAYER_KHRONOS_validation + synchronization validation + messenger
  bool int64 = true;        // enable shaderInt64 where the device has it; false: act as a device without it
};

// A window to present to (the demo): the instance extensions its surface needs
// (glfwGetRequiredInstanceExtensions) and a function making the surface once the instance exists.
// The surface is owned by the context.
struct WindowSurface {
  std::vector<std::string> instance_extensions;
  std::function<VkSurfaceKHR(VkInstance)> make_surface;
};

class Context {
 public:
  // Throws RuntimeError when Vulkan, the validation layer (if asked) or a device is missing.
  explicit Context(const ContextOptions& options, const WindowSurface& window = {});
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const vk::raii::Device& device() const { return device_; }
  const vk::raii::PhysicalDevice& physical() const { return physical_; }
  const vk::raii::Queue& queue() const { return queue_; }
  std::uint32_t queue_family() const { return family_; }
  const vk::raii::Instance& instance() const { return instance_; }
  // The window's surface (null without a WindowSurface); the queue can present to it.
  const vk::raii::SurfaceKHR& surface() const { return surface_; }
  const std::string& device_name() const { return device_name_; }
  // shaderInt64 is enabled (where the device has it and the options allow): the step shader's
  // 64-bit-store variant.
  bool has_int64() const { return int64_; }
  // The device's subgroup size (VkPhysicalDeviceVulkan11Properties): the invocations it runs in
  // lock step (llvmpipe: 8 per AVX2 register; NVIDIA 32; AMD 32 or 64).
  std::uint32_t subgroup_size() const { return subgroup_size_; }
  // The device's float controls for 32-bit floats (VkPhysicalDeviceVulkan12Properties): whether a
  // shader may declare DenormPreserve and SignedZeroInfNanPreserve, which the exact path needs for
  // bit-identity to be guaranteed rather than observed (gpu/float_policy.h).
  bool denorm_preserve() const { return denorm_preserve_; }
  bool signed_zero_preserve() const { return signed_zero_preserve_; }
  // The driver as it names itself ("llvmpipe", "NVIDIA", ...: driverID, driverName, driverInfo) and
  // the device's Vulkan version, for reports.
  vk::DriverId driver_id() const { return driver_id_; }
  const std::string& driver() const { return driver_; }
  std::uint32_t api_version() const { return api_version_; }
  // Host writes to non-coherent memory are flushed, and device writes invalidated, in whole atoms.
  vk::DeviceSize non_coherent_atom() const { return non_coherent_atom_; }
  // Validation messages so far (empty without validation).
  const ValidationLog& validation_log() const { return *log_; }

  // Waits for the device to be idle before what it may still use is destroyed (destructors): a lost
  // device has nothing left to wait for, so its error is not thrown.
  void wait_idle_for_teardown() const noexcept;

  // Records commands into a fresh primary command buffer, submits it and waits for it (see also
  // Submitter below, for work submitted every frame).
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
  bool int64_ = false;
  std::uint32_t subgroup_size_ = 1;
  bool denorm_preserve_ = false, signed_zero_preserve_ = false;
  vk::DriverId driver_id_{};
  std::string driver_;
  std::uint32_t api_version_ = 0;
  vk::DeviceSize non_coherent_atom_ = 1;
  vk::raii::Context loader_;
  vk::raii::Instance instance_ = nullptr;
  std::optional<vk::raii::DebugUtilsMessengerEXT> messenger_;
  vk::raii::SurfaceKHR surface_ = nullptr;
  vk::raii::PhysicalDevice physical_ = nullptr;
  std::uint32_t family_ = 0;
  std::string device_name_;
  vk::raii::Device device_ = nullptr;
  vk::raii::Queue queue_ = nullptr;
  vk::raii::CommandPool pool_ = nullptr;
};

// One primary command buffer and one fence, reused: Context::submit_and_wait() without creating
// a command buffer and a fence per call (the renderer's per-frame compute). Its own command pool,
// so it does not share the context's (pools are externally synchronized). Not thread-safe; the
// context must outlive it.
class Submitter {
 public:
  Submitter(const Context& ctx, const std::string& name);

  // Records commands into the command buffer (reset first), submits it and waits for it.
  void submit_and_wait(const std::function<void(const vk::raii::CommandBuffer&)>& record);

 private:
  const Context* ctx_;
  vk::raii::CommandPool pool_ = nullptr;
  vk::raii::CommandBuffer cmd_ = nullptr;
  vk::raii::Fence fence_ = nullptr;
};

}  // namespace pond::gpu
