#include <cstdio>
#include <cstdlib>

#include "targets.h"

namespace pond::fuzz {
namespace {

PropertyHandler handler = nullptr;

}  // namespace

void set_property_handler(PropertyHandler h) { handler = h; }

void property_failed(const char* what) {
  if (handler) handler(what);  // the replay test's: throws
  std::fprintf(stderr, "fuzz property failed: %s\n", what);
  std::abort();
}

}  // namespace pond::fuzz
