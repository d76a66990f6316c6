// pond: parses the command line and dispatches to one subcommand. Errors are exceptions caught here
// once: bad input (InputError, CLI11 parse errors) exits 2, run-time failures and internal errors
// (core/errors.h) exit 1, each with one line on stderr; a command stopped by a signal exits 128 +
// the signal (core/interrupt.h). Messages escape the user's text where they quote it (core/text.h);
// report() makes sure of one line.
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "app/command_line.h"
#include "core/interrupt.h"
#include "core/errors.h"
#include "core/text.h"

namespace {
void report(const char* prefix, const char* what) {
  std::fprintf(stderr, "pond: %s%s\n", prefix, pond::printable_line(what).c_str());
}
}  // namespace

int main(int argc, char** argv) {
  pond::install_signal_handling();
  try {
    pond::app::CommandLine command_line;
    const pond::app::CommandLine::Parsed parsed = command_line.parse(argc, argv);
    if (!parsed.command) return parsed.exit_code;
    return parsed.command->run();
  } catch (const pond::Interrupted& e) {  // a signal: 128 + the signal, as a shell reports it
    report("", e.what());
    return 128 + e.signal;
  } catch (const pond::InputError& e) {
    report("", e.what());
    return 2;
  } catch (const pond::InternalError& e) {  // a broken invariant: pond's fault, not the user's
    report("internal error: ", e.what());
    return 1;
  } catch (const pond::RuntimeError& e) {
    report("", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "pond: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    report("", e.what());
    return 1;
  }
}
