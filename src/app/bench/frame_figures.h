#pragma once
// A rendered frame of the demo's scene with the wind tree and 8 bodies (scenes/demo_257_bodies.json,
// scaled to the plan's grid) at the plan's size: frames with every effect on and with every effect
// off, alternated, each waited for; the process's CPU time of each (every thread, the driver's too);
// and each pass's GPU time from timestamp queries in those very frames (where the device has none,
// the report says so and the frames still run).
#include "app/bench/plan.h"
#include "app/bench/progress.h"
#include "app/bench/report.h"
#include "gpu/context.h"

namespace pond::bench {

void measure_frame(const gpu::Context& ctx, const Plan& plan, Progress& progress, Report& report);

}  // namespace pond::bench
