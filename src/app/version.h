#pragma once
// `pond --version`'s one line, also the first line of `pond check`'s report, so a result says which
// build made it: the version (plus `git describe` when built from a checkout), the CPU backends in
// this build and the Vulkan headers it was compiled against ("no Vulkan" in CPU-only builds).
#include <string>

namespace pond::app {

// e.g. "pond 0.1.0 (git 833c926), CPU backends scalar sse avx2 avx512, Vulkan headers 1.3.239"
std::string version_line();

}  // namespace pond::app
