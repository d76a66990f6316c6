#pragma once
// A small persistent pool that runs one function on `parts` contiguous parts of a job per call, the
// calling thread taking part 0. Waking parked threads is cheap next to a large grid's substep;
// small grids, where it would not be, use fewer parts (cpu_solver.cpp).
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace pond::sim {

class RowThreads {
 public:
  explicit RowThreads(int threads);  // total threads including the caller, >= 1
  ~RowThreads();
  RowThreads(const RowThreads&) = delete;
  RowThreads& operator=(const RowThreads&) = delete;

  int size() const { return static_cast<int>(workers_.size()) + 1; }
  // Calls fn(part) for part in [0, parts), parts <= size(), and returns when all are done.
  void run(int parts, const std::function<void(int)>& fn);

 private:
  void work(int index);
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int)>* job_ = nullptr;
  int parts_ = 0;
  int pending_ = 0;
  unsigned generation_ = 0;
  bool stop_ = false;
};

}  // namespace pond::sim
