#include "app/check_bridge.h"
#include "core/errors.h"

namespace pond::app {

int run_check(const CheckOptions&) {
  throw InputError("check: this build has no GPU solver to check (IA-32 builds are CPU-only)");
}

}  // namespace pond::app
