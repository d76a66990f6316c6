#pragma once
// A Vulkan instance and device made through the loader with VK_LAYER_POND_discrete_gpu switched on
// by the environment, as any program would get them: the base of the layer's tests. The device
// has timeline semaphores (Vulkan 1.2) and nothing else optional.
//
// CTest sets VK_LAYER_PATH (the validation layer's directory, then build/layers) and
// VK_INSTANCE_LAYERS (validation first), so that validation sits above the layer and checks the
// presented device, and MESA_SHADER_CACHE_DIR and XDG_RUNTIME_DIR; a run by hand gets the same
// defaults. Validation messages are collected, not printed: tests that break a rule on purpose
// expect the message, every other test expects none.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "gpu/vulkan.h"

namespace pond::layer_test {

// A buffer in host-visible memory, mapped whole (what the application sees is the layer's shadow).
struct HostBuffer {
  vk::raii::Buffer buffer = nullptr;
  vk::raii::DeviceMemory memory = nullptr;
  vk::DeviceSize size = 0;
  vk::DeviceSize allocation_size = 0;  // its memory's, mapped whole
  std::byte* mapped = nullptr;
};

class LayerDevice {
 public:
  // `app_layers`: layers the application itself enables (the environment's come on top of them).
  explicit LayerDevice(const std::vector<const char*>& app_layers = {});
  ~LayerDevice();
  LayerDevice(const LayerDevice&) = delete;
  LayerDevice& operator=(const LayerDevice&) = delete;

  const vk::raii::PhysicalDevice& physical() const { return physical_; }
  const vk::raii::Device& device() const { return device_; }
  const vk::raii::Queue& queue() const { return queue_; }

  // The first memory type in `type_bits` with all of `required` and none of `forbidden`; throws
  // when there is none.
  std::uint32_t memory_type(std::uint32_t type_bits, vk::MemoryPropertyFlags required,
                            vk::MemoryPropertyFlags forbidden = {}) const;
  // A transfer source and destination buffer in host-visible memory, mapped.
  HostBuffer host_buffer(vk::DeviceSize size) const;
  // Records with `record`, submits, waits (vkQueueWaitIdle).
  void submit(const std::function<void(const vk::raii::CommandBuffer&)>& record) const;
  // vkFlushMappedMemoryRanges / vkInvalidateMappedMemoryRanges of one range, the raw result.
  VkResult flush(const vk::raii::DeviceMemory& memory, vk::DeviceSize offset, vk::DeviceSize size) const;
  VkResult invalidate(const vk::raii::DeviceMemory& memory, vk::DeviceSize offset, vk::DeviceSize size) const;

  // The validation messages since the last call.
  std::vector<std::string> take_messages();

 private:
  std::vector<std::string> messages_;  // before the messenger that appends to it
  vk::raii::Context context_;
  vk::raii::Instance instance_ = nullptr;
  vk::raii::DebugUtilsMessengerEXT messenger_ = nullptr;
  vk::raii::PhysicalDevice physical_ = nullptr;
  std::uint32_t family_ = 0;
  vk::raii::Device device_ = nullptr;
  vk::raii::Queue queue_ = nullptr;
  vk::raii::CommandPool pool_ = nullptr;
};

// Joined messages, for a test's failure output.
std::string joined(const std::vector<std::string>& messages);

}  // namespace pond::layer_test
