#pragma once
// The machine a bench ran on, as the JSON names it: the CPU's model, its logical CPUs, the SIMD
// sets pond's solver may use on it, its memory, and the load other work put on it as the run began
// (Linux: /proc/cpuinfo, /proc/meminfo, /proc/loadavg).
#include "app/bench/report.h"

namespace pond::bench {

Machine this_machine();

}  // namespace pond::bench
