#pragma once
// What the signals that end a process do to pond (install_signal_handling(), first thing in main):
//  - SIGINT, SIGTERM, SIGHUP and SIGQUIT. While a command polls (an InterruptScope lives: pond
//    simulate, pond check), the first only records itself and the command stops at its next check:
//    throw_if_interrupted() unwinds to main, which prints one line and exits 128 + the signal.
//    Blocking reads are interrupted too (no SA_RESTART), so a read waiting on a FIFO with no writer
//    stops. Otherwise, and for a second signal, pond ends at once from the handler: the temporary
//    file of an atomic write in progress is removed, one line is written, exit 128 + the signal.
//  - SIGPIPE and SIGXFSZ are ignored: a closed pipe or a file size limit (ulimit -f) becomes the
//    write's error (EPIPE, EFBIG), reported as any failed write: exit 1, one line, no temp file.
// The handler only sets a flag or calls unlink, write and _exit, all async-signal-safe.
#include <csignal>
#include <stdexcept>
#include <string>

namespace pond {

inline volatile std::sig_atomic_t g_interrupt_signal = 0;

// What reaches main when a signal stopped a command.
struct Interrupted : std::runtime_error {
  Interrupted(int sig, const std::string& what) : std::runtime_error(what), signal(sig) {}
  int signal;
};

const char* signal_name(int sig);  // "SIGINT", "SIGTERM", ...
void install_signal_handling();

// While one lives, the command polls: the signals above are recorded for throw_if_interrupted().
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

// From now on the signals only record themselves, a second one too: what a command writes while
// it stops (a checkpoint) is written whole before it exits.
void hold_interrupts();

// Throws Interrupted when a signal arrived; `progress` says how far the work got ("after step 10
// of 100").
void throw_if_interrupted(const std::string& progress);

// The temporary file an atomic write is filling (core/output_file.cpp), removed if a signal ends
// pond meanwhile; null: none.
void set_temporary_file(const char* path);
// One more output file written whole (what the line says when a signal ends pond).
void count_file_written();

}  // namespace pond
