// pond tree: the wind tree skeleton dump. Not built yet (its issue is open), so not registered in --help.
#include "app/commands.h"

namespace pond::app {

Command add_tree_command(CLI::App&) { return {}; }

}  // namespace pond::app
