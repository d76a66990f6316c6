#pragma once
// The `pond` command line as one object: the CLI11 app with every subcommand registered, and a
// parse step that decides what to run without running it and without exiting the process. main()
// parses and runs the chosen command; the CLI fuzz target (tests/fuzz) parses only, so it never
// touches a file. Header-only so that both link the very same setup without a library of its own.
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/version.h"
#include "core/text.h"

namespace pond::app {

class CommandLine {
 public:
  CommandLine() {
    app_.require_subcommand(0, 1);
    app_.set_version_flag("--version", [] { return version_line(); },
                          "Print the version, the CPU backends and the Vulkan headers of this build, then exit");
    commands_ = {add_demo_command(app_), add_simulate_command(app_), add_render_command(app_),
                 add_lod_command(app_), add_tree_command(app_), add_check_command(app_), add_bench_command(app_)};
  }
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  // What parse() decided: run `command`, or exit with `exit_code` (help printed, or a bad command
  // line reported as one line on stderr naming the problem: 2).
  struct Parsed {
    const Command* command = nullptr;
    int exit_code = 0;
  };

  // Parses argv (argv[0] is the program name). With `quiet`, nothing is printed (the fuzz target).
  Parsed parse(int argc, const char* const* argv, bool quiet = false) {
    try {
      app_.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == 0) {  // --help, --help-all, --version
        if (quiet) return {nullptr, 0};
        return {nullptr, app_.exit(e)};
      }
      if (!quiet) std::fprintf(stderr, "pond: %s\n", printable_line(in_our_words(e.what())).c_str());  // quotes argv as typed
      return {nullptr, 2};
    }
    for (const Command& c : commands_)
      if (c.sub && c.sub->parsed()) return {&c, 0};
    return {&commands_.front(), 0};  // no subcommand: the demo
  }

 private:
  // CLI11's message for an option given twice ("--size: At Most 1 required but received 2") in
  // pond's words; every other message as it is.
  static std::string in_our_words(std::string what) {
    const std::string at_most = ": At Most 1 required but received ";
    if (const auto k = what.find(at_most); k != std::string::npos)
      return what.substr(0, k) + " is given " + what.substr(k + at_most.size()) + " times; give it once";
    return what;
  }

  CLI::App app_{"pond: a spring-mass water surface and a tree in the wind, on Vulkan compute", "pond"};
  std::vector<Command> commands_;
};

}  // namespace pond::app
