#pragma once
// The machine a bench ran on, as the JSON names it: the CPU's model, its logical CPUs, the SIMD
// sets pond's solver may use on it, and its memory (Linux: /proc/cpuinfo, /proc/meminfo).
#include "app/bench/report.h"

namespace pond::bench {

Machine this_machine();

}  // namespace pond::bench
