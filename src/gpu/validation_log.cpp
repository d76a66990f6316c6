#include "gpu/validation_log.h"

#include <cstdio>
#include <cstring>

namespace pond::gpu {
namespace {

// The loader's own notices (it says so when VK_INSTANCE_LAYERS adds layers, as in the test layer's
// runs) are general-purpose warnings, not findings about pond's use of Vulkan.
bool is_loader_notice(VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT type,
                      const VkDebugUtilsMessengerCallbackDataEXT* data) {
  return severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT && type == VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT &&
         data->pMessageIdName && std::strcmp(data->pMessageIdName, "Loader Message") == 0;
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT type,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                          void* user) {
  if (is_loader_notice(severity, type, data)) return VK_FALSE;
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
