#include "app/bench/progress.h"

#include <cstdio>
#include <unistd.h>

namespace pond::bench {

Progress::Progress() : tty_(::isatty(2) != 0) {}

Progress::~Progress() {
  if (tty_ && shown_) std::fprintf(stderr, "\r%*s\r", static_cast<int>(shown_), "");
}

void Progress::show(const std::string& what) {
  if (!tty_) return;
  const std::string line = "pond bench: " + what;
  std::fprintf(stderr, "\r%-*s", static_cast<int>(shown_), line.c_str());
  std::fflush(stderr);
  shown_ = std::max(shown_, line.size());
}

}  // namespace pond::bench
