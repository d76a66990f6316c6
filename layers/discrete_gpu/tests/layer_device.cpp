#include "layer_device.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace pond::layer_test {
namespace {

constexpr const char* kLayer = "VK_LAYER_POND_discrete_gpu";
constexpr const char* kValidation = "VK_LAYER_KHRONOS_validation";

// Runs before main, so before the loader or Mesa read the environment. CTest's values win.
const bool kEnvironmentSet = [] {
  std::filesystem::create_directories(POND_TEST_MESA_CACHE_DIR);
  std::filesystem::create_directories(POND_TEST_XDG_RUNTIME_DIR);
  std::filesystem::permissions(POND_TEST_XDG_RUNTIME_DIR, std::filesystem::perms::owner_all,
                               std::filesystem::perm_options::replace);
  ::setenv("VK_LAYER_PATH", POND_TEST_LAYER_PATH, 0);
  ::setenv("VK_INSTANCE_LAYERS", "VK_LAYER_KHRONOS_validation:VK_LAYER_POND_discrete_gpu", 0);
  ::setenv("MESA_SHADER_CACHE_DIR", POND_TEST_MESA_CACHE_DIR, 0);
  ::setenv("XDG_RUNTIME_DIR", POND_TEST_XDG_RUNTIME_DIR, 0);
  return true;
}();

VKAPI_ATTR VkBool32 VKAPI_CALL collect(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                       const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  static_cast<std::vector<std::string>*>(user)->emplace_back(data->pMessage ? data->pMessage : "(no text)");
  return VK_FALSE;  // let the call through: the tests look at what the layer below does with it
}

}  // namespace

std::string joined(const std::vector<std::string>& messages) {
  std::string all;
  for (const std::string& m : messages) all += m + "\n";
  return all;
}

LayerDevice::LayerDevice(const std::vector<const char*>& app_layers) {
  if (!kEnvironmentSet) throw std::logic_error("environment not set");
  const auto available = context_.enumerateInstanceLayerProperties();
  for (const char* needed : {kLayer, kValidation})
    if (std::none_of(available.begin(), available.end(),
                     [&](const vk::LayerProperties& l) { return l.layerName == std::string(needed); }))
      throw std::runtime_error(std::string(needed) + " is not in VK_LAYER_PATH (" + std::getenv("VK_LAYER_PATH") + ")");

  const vk::ApplicationInfo app{.pApplicationName = "pond layer tests", .apiVersion = VK_API_VERSION_1_3};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  const vk::DebugUtilsMessengerCreateInfoEXT messenger_info{
      .messageSeverity = vk::DebugUtilsMessageSeverityFlagBitsEXT::eWarning |
                         vk::DebugUtilsMessageSeverityFlagBitsEXT::eError,
      .messageType = vk::DebugUtilsMessageTypeFlagBitsEXT::eValidation,
      .pfnUserCallback = collect,
      .pUserData = &messages_};
  instance_ = vk::raii::Instance(
      context_, vk::InstanceCreateInfo{.pNext = &messenger_info,
                                       .pApplicationInfo = &app,
                                       .enabledLayerCount = static_cast<std::uint32_t>(app_layers.size()),
                                       .ppEnabledLayerNames = app_layers.data(),
                                       .enabledExtensionCount = 1,
                                       .ppEnabledExtensionNames = extensions});
  messenger_ = vk::raii::DebugUtilsMessengerEXT(instance_, messenger_info);
  physical_ = std::move(vk::raii::PhysicalDevices(instance_).front());

  const auto families = physical_.getQueueFamilyProperties();
  while (family_ < families.size() && !(families[family_].queueFlags & vk::QueueFlagBits::eCompute)) ++family_;
  if (family_ == families.size()) throw std::runtime_error("no compute queue");
  const float priority = 1.0f;
  const vk::DeviceQueueCreateInfo queue_info{.queueFamilyIndex = family_, .queueCount = 1,
                                             .pQueuePriorities = &priority};
  const vk::PhysicalDeviceVulkan12Features timeline{.timelineSemaphore = VK_TRUE};  // for vkWaitSemaphores
  device_ = vk::raii::Device(physical_, vk::DeviceCreateInfo{.pNext = &timeline, .queueCreateInfoCount = 1,
                                                             .pQueueCreateInfos = &queue_info});
  queue_ = vk::raii::Queue(device_, family_, 0);
  pool_ = vk::raii::CommandPool(device_, vk::CommandPoolCreateInfo{.queueFamilyIndex = family_});
}

LayerDevice::~LayerDevice() {
  if (*device_) device_.waitIdle();
}

std::uint32_t LayerDevice::memory_type(std::uint32_t type_bits, vk::MemoryPropertyFlags required,
                                       vk::MemoryPropertyFlags forbidden) const {
  const auto props = physical_.getMemoryProperties();
  for (std::uint32_t t = 0; t < props.memoryTypeCount; ++t) {
    const vk::MemoryPropertyFlags flags = props.memoryTypes[t].propertyFlags;
    if ((type_bits & (1u << t)) && (flags & required) == required && !(flags & forbidden)) return t;
  }
  throw std::runtime_error("no memory type with " + vk::to_string(required) + " and without " + vk::to_string(forbidden));
}

HostBuffer LayerDevice::host_buffer(vk::DeviceSize size) const {
  HostBuffer b;
  b.size = size;
  const vk::BufferUsageFlags usage = vk::BufferUsageFlagBits::eTransferSrc | vk::BufferUsageFlagBits::eTransferDst;
  b.buffer = vk::raii::Buffer(device_, vk::BufferCreateInfo{.size = size, .usage = usage});
  const vk::MemoryRequirements req = b.buffer.getMemoryRequirements();
  const std::uint32_t type = memory_type(req.memoryTypeBits, vk::MemoryPropertyFlagBits::eHostVisible);
  b.memory = vk::raii::DeviceMemory(device_, vk::MemoryAllocateInfo{.allocationSize = req.size, .memoryTypeIndex = type});
  b.allocation_size = req.size;
  b.buffer.bindMemory(*b.memory, 0);
  b.mapped = static_cast<std::byte*>(b.memory.mapMemory(0, VK_WHOLE_SIZE));
  return b;
}

void LayerDevice::submit(const std::function<void(const vk::raii::CommandBuffer&)>& record) const {
  vk::raii::CommandBuffers buffers(device_, vk::CommandBufferAllocateInfo{
                                                .commandPool = *pool_, .level = vk::CommandBufferLevel::ePrimary,
                                                .commandBufferCount = 1});
  const vk::raii::CommandBuffer& cmd = buffers[0];
  cmd.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  record(cmd);
  // The host reads what the transfer wrote only after a barrier to the host (then an invalidate).
  const vk::MemoryBarrier to_host{.srcAccessMask = vk::AccessFlagBits::eTransferWrite,
                                  .dstAccessMask = vk::AccessFlagBits::eHostRead};
  cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost, {}, to_host, nullptr,
                      nullptr);
  cmd.end();
  const vk::CommandBuffer handle = *cmd;
  queue_.submit(vk::SubmitInfo{.commandBufferCount = 1, .pCommandBuffers = &handle});
  queue_.waitIdle();
}

VkResult LayerDevice::flush(const vk::raii::DeviceMemory& memory, vk::DeviceSize offset, vk::DeviceSize size) const {
  const VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, *memory, offset, size};
  return device_.getDispatcher()->vkFlushMappedMemoryRanges(*device_, 1, &range);
}

VkResult LayerDevice::invalidate(const vk::raii::DeviceMemory& memory, vk::DeviceSize offset,
                                 vk::DeviceSize size) const {
  const VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, *memory, offset, size};
  return device_.getDispatcher()->vkInvalidateMappedMemoryRanges(*device_, 1, &range);
}

std::vector<std::string> LayerDevice::take_messages() {
  std::vector<std::string> taken;
  taken.swap(messages_);
  return taken;
}

}  // namespace pond::layer_test
