#include <cstdio>
#include <cstdlib>

#include "targets.h"

namespace pond::fuzz {

void property_failed(const char* what) {
  std::fprintf(stderr, "fuzz property failed: %s\n", what);
  std::abort();
}

}  // namespace pond::fuzz
