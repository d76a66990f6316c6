// pond render: headless rendering to PNG. Not built yet (its issue is open), so not registered in --help.
#include "app/commands.h"

namespace pond::app {

Command add_render_command(CLI::App&) { return {}; }

}  // namespace pond::app
