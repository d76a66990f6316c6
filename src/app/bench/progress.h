#pragma once
// `pond bench`'s progress on a terminal: one line on stderr, rewritten as each figure starts, and
// cleared at the end. Silent when stderr is not a terminal (CI logs, tests).
#include <string>

namespace pond::bench {

class Progress {
 public:
  Progress();
  ~Progress();  // clears the line
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void show(const std::string& what);  // "cpu: avx2, 1 thread, 256²"

 private:
  bool tty_;
  std::size_t shown_ = 0;
};

}  // namespace pond::bench
