#include "app/render_bridge.h"
#include "core/errors.h"

namespace pond::app {

int run_render(const RenderOptions&) {
  throw InputError("render: this build has no renderer (IA-32 builds are CPU-only and headless)");
}

}  // namespace pond::app
