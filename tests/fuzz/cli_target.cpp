// Fuzz target: the real `pond` command line (app/command_line.h: every subcommand's CLI11 options),
// parse only: the chosen command is never run, so no file is read or written. The input is argv
// after the program name, one argument per line. Each argument is also given to the shared value
// parsers the commands call after parsing (WxH sizes, X,Y,Z vectors).
#include <string>
#include <vector>

#include "app/cli_parse.h"
#include "app/command_line.h"
#include "core/errors.h"
#include "targets.h"

namespace pond::fuzz {

int cli(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> args = {"pond"};
  std::size_t start = 0;
  while (start <= text.size() && args.size() < 65) {
    const std::size_t nl = text.find('\n', start);
    const std::size_t end = nl == std::string::npos ? text.size() : nl;
    args.push_back(text.substr(start, end - start));
    if (nl == std::string::npos) break;
    start = nl + 1;
  }
  if (args.back().empty()) args.pop_back();  // a trailing newline ends the last argument
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());

  app::CommandLine command_line;
  const app::CommandLine::Parsed parsed =
      command_line.parse(static_cast<int>(argv.size()), argv.data(), /*quiet=*/true);
  if (!parsed.command && parsed.exit_code != 0 && parsed.exit_code != 2)
    property_failed("a bad command line must exit 2");
  if (parsed.command && !parsed.command->run) property_failed("a parsed command without an action");

  for (std::size_t k = 1; k < args.size(); ++k) {
    try {
      const app::Size2 s = app::parse_size(args[k], "--size");
      if (s.width < 1 || s.height < 1 || s.width > 65536 || s.height > 65536)
        property_failed("parse_size accepted a size out of range");
    } catch (const InputError&) {
    }
    try {
      app::parse_vec3(args[k], "--eye");
    } catch (const InputError&) {
    }
  }
  return 0;
}

}  // namespace pond::fuzz
