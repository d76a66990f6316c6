#pragma once
// Messages of the validation layer (and of any other layer), collected so tests can require that
// there were none. Warnings and errors are kept and echoed to stderr; info and verbose messages
// are ignored, and so is every message of the loader (validation_log.cpp says why).
#include <mutex>
#include <string>
#include <vector>

#include "gpu/vulkan.h"

namespace pond::gpu {

class ValidationLog {
 public:
  void add(std::string message);
  std::vector<std::string> messages() const;
  std::size_t count() const;

  // The create-info of a messenger reporting into this log (also chained into instance creation).
  vk::DebugUtilsMessengerCreateInfoEXT messenger_info();

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> messages_;
};

}  // namespace pond::gpu
