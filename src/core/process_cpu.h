#pragma once
// The CPU time this process has used, every thread of it: pond's own and its Vulkan driver's. On a
// CPU device (lavapipe) the driver's threads are the "GPU", so a frame's CPU time over the cores
// the machine has is the least wall time that frame can take, however its work is overlapped.

namespace pond::core {

// User plus system time of every thread of the process so far, in milliseconds.
double process_cpu_ms();

// The process's CPU time in laps: each lap() is what was used since the last one (or since made).
class CpuLaps {
 public:
  double lap() {
    const double now = process_cpu_ms(), ms = now - mark_;
    mark_ = now;
    return ms;
  }

 private:
  double mark_ = process_cpu_ms();
};

}  // namespace pond::core
