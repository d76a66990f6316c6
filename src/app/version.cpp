#include "app/version.h"

#include "app/gpu_bridge.h"
#include "pond_version.h"  // POND_VERSION, POND_GIT_DESCRIBE: generated at build time (cmake/Version.cmake)
#include "sim/backends.h"

namespace pond::app {

std::string version_line() {
  std::string line = std::string("pond ") + POND_VERSION;
  if (*POND_GIT_DESCRIBE) line += std::string(" (git ") + POND_GIT_DESCRIBE + ")";
  line += ", CPU backends";
  for (sim::Backend b : sim::kBackends)
    if (sim::compiled_in(b)) line += std::string(" ") + sim::backend_name(b);
  return line + ", " + vulkan_in_build();
}

}  // namespace pond::app
