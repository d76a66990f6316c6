#pragma once
// The demo's frame-time totals over a run (the first frame, which carries pipeline and allocation
// warm-up, left out) and the one-line summary `pond demo --frames N` prints at the end, with the
// CPU time the process used over those frames (core/process_cpu.h: on a CPU device, the driver's
// rendering too), so the summary says how many cores the frames kept busy.
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/process_cpu.h"
#include "render/frame_loop.h"

namespace pond::app::demo {

struct RunTotals {
  std::int64_t drawn = 0;  // frames drawn, the first included
  double total_ms = 0, simulate_ms = 0, acquire_ms = 0, present_ms = 0;
  double cpu_ms = 0;  // the process's CPU time over the counted frames
  core::CpuLaps cpu;   // a lap a frame, from one frame's end to the next
  render::FrameStats sum{};

  void add(double frame_ms, const render::FrameStats& last, double simulate, double acquire, double present) {
    const double cpu_frame = cpu.lap();
    if (drawn++ == 0) return;
    total_ms += frame_ms;
    cpu_ms += cpu_frame;
    sum.wait_ms += last.wait_ms, sum.lod_ms += last.lod_ms, sum.draw_ms += last.draw_ms;
    sum.triangles += last.triangles;
    simulate_ms += simulate, acquire_ms += acquire, present_ms += present;
  }

  // "pond demo: N frames at WxH on DEVICE, SOLVER, MODE: ms/frame (FPS); simulate, wait, LOD, draw,
  // acquire, present ms; triangles; CPU ms a frame (cores busy)"
  void print(unsigned width, unsigned height, const std::string& device, const std::string& solver,
             const std::string& present_mode, std::size_t full_triangles) const {
    if (drawn < 2) return;
    const double n = static_cast<double>(drawn - 1);
    std::printf("pond demo: %lld frames at %ux%u on %s, %s, %s: %.2f ms/frame (%.1f FPS); simulate %.2f, wait %.2f, "
                "LOD %.2f, draw %.2f, acquire %.2f, present %.2f ms; %.0f of %zu triangles; CPU %.2f ms a frame "
                "(%.2f cores busy)\n",
                static_cast<long long>(drawn), width, height, device.c_str(), solver.c_str(), present_mode.c_str(),
                total_ms / n, 1000.0 * n / total_ms, simulate_ms / n, sum.wait_ms / n, sum.lod_ms / n, sum.draw_ms / n,
                acquire_ms / n, present_ms / n, static_cast<double>(sum.triangles) / n, full_triangles,
                cpu_ms / n, total_ms > 0 ? cpu_ms / total_ms : 0.0);
  }
};

}  // namespace pond::app::demo
