#pragma once
// Options of a headless context (compute, offscreen): a device name and validation, nothing of a
// window. Built by assignment so callers keep compiling as ContextOptions grows window fields.
#include <string>
#include <utility>

#include "gpu/context.h"

namespace pond::gpu {

inline ContextOptions headless_options(std::string device, bool validation) {
  ContextOptions o;
  o.device = std::move(device);
  o.validation = validation;
  return o;
}

}  // namespace pond::gpu
