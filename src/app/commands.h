#pragma once
// Each `pond` subcommand registers its options on the CLI11 app and returns the action to run once
// parsing succeeded. main() only parses and dispatches.
#include <CLI/CLI.hpp>
#include <functional>

namespace pond::app {

// A registered subcommand (`sub` is null for the default command, run when none is named) and
// what to run when it was chosen; the options it reads are captured by `run`.
struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;
};

Command add_demo_command(CLI::App& app);  // also the default when no subcommand is named
Command add_simulate_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_lod_command(CLI::App& app);
Command add_tree_command(CLI::App& app);
Command add_check_command(CLI::App& app);  // the parity suite on the chosen device
Command add_bench_command(CLI::App& app);  // the headline figures on this machine

}  // namespace pond::app
