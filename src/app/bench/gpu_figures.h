#pragma once
// The figures that need a Vulkan device: the GPU solver (exact and fast math), a rendered frame
// (every effect on and off, each pass's GPU time from timestamp queries) and the bodies' cost on
// the GPU solver. gpu_figures.cpp in
// Vulkan builds; gpu_figures_none.cpp, which notes that they were skipped, in the others (IA-32).
#include "app/bench/plan.h"
#include "app/bench/progress.h"
#include "app/bench/report.h"

namespace pond::bench {

// Runs the "gpu" and "frame" groups and the GPU's part of "bodies" on one device; fills report.device. Without
// Vulkan or a device, a note (RuntimeError when --only named the groups); RuntimeError for a
// validation message when the plan asks for validation.
void measure_gpu_groups(const Plan& plan, Progress& progress, Report& report);

}  // namespace pond::bench
