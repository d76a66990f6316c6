#pragma once
// Stopping a long command cleanly on SIGINT (Ctrl-C) or SIGTERM. While an InterruptScope lives, the
// two signals only record themselves (the handler does nothing else, so it is async-signal-safe);
// the command's loop calls throw_if_interrupted() between chunks of work, which unwinds to main
// before anything is written: no output under the requested name, no temporary file. main prints
// one line and exits 128 + the signal number (130 for SIGINT, 143 for SIGTERM), what a shell
// reports for a process the signal killed. A second signal while stopping kills the process at
// once (SA_RESETHAND), for a user who does not want to wait.
//
// Only commands that poll install the scope (pond simulate); elsewhere the signals keep their
// default action, and the atomic output files still never leave a partial file under the
// requested name. Header-only: main.cpp and the commands share it without a library of its own.
#include <csignal>
#include <stdexcept>
#include <string>

namespace pond::app {

inline volatile std::sig_atomic_t g_interrupt_signal = 0;

// What reaches main when a signal stopped a command.
struct Interrupted : std::runtime_error {
  Interrupted(int sig, const std::string& what) : std::runtime_error(what), signal(sig) {}
  int signal;
};

inline const char* signal_name(int sig) { return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal"; }

class InterruptScope {
 public:
  InterruptScope() {
    g_interrupt_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = [](int sig) { g_interrupt_signal = sig; };
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART | SA_RESETHAND;
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
  }
  ~InterruptScope() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

// Throws Interrupted when a signal arrived; `progress` says how far the work got ("after step 10
// of 100").
inline void throw_if_interrupted(const std::string& progress) {
  if (const int sig = g_interrupt_signal)
    throw Interrupted(sig, std::string("interrupted by ") + signal_name(sig) + " " + progress +
                               "; nothing was written");
}

}  // namespace pond::app
