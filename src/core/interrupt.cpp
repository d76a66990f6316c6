#include "core/interrupt.h"

#include <cstring>
#include <unistd.h>

namespace pond {
namespace {

volatile std::sig_atomic_t g_polling = 0;  // an InterruptScope lives
volatile std::sig_atomic_t g_holding = 0;  // hold_interrupts(): record every signal
char g_temporary[4096];                    // the temporary file, "" for none
volatile std::sig_atomic_t g_has_temporary = 0;
volatile std::sig_atomic_t g_files_written = 0;  // whole output files so far

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

void write_all(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(2, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

extern "C" void on_signal(int sig) {
  if (g_holding || (g_polling && !g_interrupt_signal)) {
    g_interrupt_signal = sig;
    return;
  }
  if (g_has_temporary) ::unlink(g_temporary);
  write_all("pond: interrupted by ");
  write_all(signal_name(sig));
  if (g_files_written > 0) write_all(g_has_temporary ? "; the files written so far are whole, the one being written was removed\n"
                                                     : "; the files written so far are whole\n");
  else write_all(g_has_temporary ? "; nothing was written (the file being written was removed)\n" : "; nothing was written\n");
  ::_exit(128 + sig);
}

void handle(bool restart) {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (int s : kSignals) sigaddset(&sa.sa_mask, s);
  sa.sa_flags = restart ? SA_RESTART : 0;
  for (int s : kSignals) sigaction(s, &sa, nullptr);
}

}  // namespace

const char* signal_name(int sig) {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    case SIGQUIT: return "SIGQUIT";
    default: return "a signal";
  }
}

void install_signal_handling() {
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  handle(true);
}

InterruptScope::InterruptScope() {
  g_interrupt_signal = 0;
  g_polling = 1;
  handle(false);  // a blocking read returns EINTR instead of waiting on
}

InterruptScope::~InterruptScope() {
  g_polling = 0;
  handle(true);
}

void hold_interrupts() { g_holding = 1; }

void throw_if_interrupted(const std::string& progress) {
  if (const int sig = g_interrupt_signal)
    throw Interrupted(sig, std::string("interrupted by ") + signal_name(sig) + " " + progress +
                               "; nothing was written");
}

void count_file_written() { g_files_written = g_files_written + 1; }

void set_temporary_file(const char* path) {
  g_has_temporary = 0;
  if (!path) return;
  const std::size_t n = std::strlen(path);
  if (n >= sizeof g_temporary) return;
  std::memcpy(g_temporary, path, n + 1);
  g_has_temporary = 1;
}

}  // namespace pond
