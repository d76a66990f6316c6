#pragma once
// The figures measured on the CPU alone (no Vulkan): the CPU solver on each backend this CPU has,
// the LOD build on rain, and the bodies' cost on the CPU solver.
#include "app/bench/plan.h"
#include "app/bench/progress.h"
#include "app/bench/report.h"

namespace pond::bench {

// "cpu.<backend>.t<threads>.<size>" in node-steps/s, each with the state's hash after the run;
// sets report.hashes_agree (every run of a size takes the same steps, so every backend and thread
// count must end in the same bits).
void measure_cpu_solver(const Plan& plan, Progress& progress, Report& report);
// After both solvers ran: a note for each size where the GPU's exact math (the CPU's steps) did not
// end in the CPU's bits.
void note_gpu_hashes(const Plan& plan, Report& report);
// "lod.<side>" in ms a build, with its triangles.
void measure_lod(const Plan& plan, Progress& progress, Report& report);
// "bodies.cpu.<n>": a step's time with n bodies over the same pond's without, alternated (the GPU
// solver's, "bodies.gpu.<n>", are gpu_figures.h's).
void measure_cpu_bodies(const Plan& plan, Progress& progress, Report& report);

// A hash as the JSON and the table show it: 16 hex digits.
std::string hex_hash(std::uint64_t hash);

}  // namespace pond::bench
