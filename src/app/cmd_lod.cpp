// pond lod: the view-dependent LOD builder. Not built yet (its issue is open), so not registered in --help.
#include "app/commands.h"

namespace pond::app {

Command add_lod_command(CLI::App&) { return {}; }

}  // namespace pond::app
