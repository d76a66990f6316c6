#include "gpu/validation_log.h"

#include <cstdio>
#include <cstring>

namespace pond::gpu {
namespace {

// The loader's messages (its notices when VK_INSTANCE_LAYERS adds layers; its errors about
// drivers it cannot open, such as another architecture's ICDs that Debian's multiarch installs
// beside the native ones) are about the machine's Vulkan installation, not pond's use of Vulkan:
// the loader skips what it cannot load. They are not validation messages, at any severity.
bool is_loader_message(const VkDebugUtilsMessengerCallbackDataEXT* data) {
  return data->pMessageIdName && std::strcmp(data->pMessageIdName, "Loader Message") == 0;
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT /*type*/,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                          void* user) {
  if (is_loader_message(data)) return VK_FALSE;
  const char* level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
  std::string text = std::string("vulkan ") + level + ": " + (data->pMessage ? data->pMessage : "");
  std::fprintf(stderr, "%s\n", text.c_str());
  static_cast<ValidationLog*>(user)->add(std::move(text));
  return VK_FALSE;  // never abort the call: the test reports the message
}

}  // namespace

void ValidationLog::add(std::string message) {
  std::lock_guard lock(mutex_);
  messages_.push_back(std::move(message));
}

std::vector<std::string> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

std::size_t ValidationLog::count() const {
  std::lock_guard lock(mutex_);
  return messages_.size();
}

vk::DebugUtilsMessengerCreateInfoEXT ValidationLog::messenger_info() {
  using S = vk::DebugUtilsMessageSeverityFlagBitsEXT;
  using T = vk::DebugUtilsMessageTypeFlagBitsEXT;
  return vk::DebugUtilsMessengerCreateInfoEXT{
      .messageSeverity = S::eWarning | S::eError,
      .messageType = T::eGeneral | T::eValidation | T::ePerformance,
      .pfnUserCallback = &on_message,
      .pUserData = this};
}

}  // namespace pond::gpu
