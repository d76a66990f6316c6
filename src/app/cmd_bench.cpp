// pond bench: pond's headline figures on this machine (app/bench/): the CPU solver on each backend,
// the GPU solver, the LOD build, a rendered frame with each pass's GPU time, the bodies' cost. A
// table on stdout, the same as JSON with --json, and ratios against an earlier JSON with --compare.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/bench/compare.h"
#include "app/bench/cpu_figures.h"
#include "app/bench/gpu_figures.h"
#include "app/bench/machine.h"
#include "app/bench/plan.h"
#include "app/bench/progress.h"
#include "app/bench/report_json.h"
#include "app/bench/table.h"
#include "app/commands.h"
#include "core/interrupt.h"
#include "core/errors.h"
#include "core/output_file.h"
#include "pond_version.h"  // POND_VERSION (cmake/Version.cmake)

namespace pond::app {
namespace {

struct BenchOptions {
  bench::Plan plan;
  std::string json, compare, tolerance = "20";
};

// "20", "20%" or "7.5 %" -> 0.2, 0.2, 0.075; InputError otherwise.
double parse_tolerance(std::string text) {
  while (!text.empty() && (text.back() == '%' || text.back() == ' ')) text.pop_back();
  char* end = nullptr;
  const double percent = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (!std::isfinite(percent) || end != text.c_str() + text.size() || percent < 0 || percent >= 100)
    throw InputError("--tolerance: '" + text + "' is not a percentage from 0 to 100 (e.g. 20 or 20%)");
  return percent / 100;
}

std::string today_utc() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &utc);
  return text;
}

int run_bench(const BenchOptions& o) {
  // Every input is checked before anything runs: a bad one costs nothing and writes nothing.
  bench::check_groups(o.plan.only);
  const double tolerance = parse_tolerance(o.tolerance);
  if (!o.json.empty()) check_output_path(o.json);
  std::optional<bench::Report> baseline;
  if (!o.compare.empty()) baseline = bench::from_json(read_file(o.compare), o.compare);

  const InterruptScope interrupt_scope;
  bench::Report report;
  report.version = POND_VERSION, report.date = today_utc(), report.quick = o.plan.quick;
  report.machine = bench::this_machine();
  if (report.machine.load_average > 0.5 * report.machine.cores)
    report.notes.push_back("the machine was busy as the run began (load " + std::to_string(report.machine.load_average).substr(0, 4) +
                           " on " + std::to_string(report.machine.cores) + " cores): expect slower, noisier figures");
  {
    bench::Progress progress;
    const bench::Plan& plan = o.plan;
    // The GPU's first: a --device that names no device is bad input, found before the long runs.
    bench::measure_gpu_groups(plan, progress, report);
    throw_if_interrupted("after the GPU's figures");
    if (plan.runs("cpu")) bench::measure_cpu_solver(plan, progress, report);
    bench::note_gpu_hashes(plan, report);
    throw_if_interrupted("after the CPU solver's figures");
    if (plan.runs("lod")) bench::measure_lod(plan, progress, report);
    throw_if_interrupted("after the LOD's figures");
    if (plan.runs("bodies")) bench::measure_cpu_bodies(plan, progress, report);
  }
  bench::print_table(report);
  if (!o.json.empty()) {
    const std::string text = bench::to_json(report);
    write_file_atomic(o.json, std::as_bytes(std::span(text)));
    std::printf("wrote %s\n", o.json.c_str());
  }
  int status = 0;
  if (!report.hashes_agree) {
    std::fprintf(stderr, "pond bench: the CPU backends' state hashes differ: %s\n", report.notes.front().c_str());
    status = 1;
  }
  if (baseline) {
    const std::vector<bench::Comparison> rows = bench::compare(report, *baseline, tolerance);
    bench::print_comparison(rows, o.compare, tolerance);
    for (const bench::Comparison& c : rows)
      if (c.regressed) {
        std::fprintf(stderr, "pond bench: %s regressed: %.3fx of %s (%s), past the tolerance of %g %%\n", c.name.c_str(),
                     c.ratio, o.compare.c_str(), c.what.c_str(), 100 * tolerance);
        status = 1;
      }
  }
  return status;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* sub = app.add_subcommand("bench", "Measure pond's headline figures on this machine (table, JSON, comparison)");
  sub->add_flag("--quick", o->plan.quick, "Small sizes and few repeats (under a minute on 2 cores)");
  sub->add_option("--json", o->json, "Also write the figures, the machine and the device as JSON (bench/schema.json)");
  sub->add_option("--compare", o->compare, "An earlier --json file: print each figure's ratio, exit 1 past --tolerance");
  sub->add_option("--tolerance", o->tolerance, "How much worse than --compare's figure is a regression, in % (default 20)");
  sub->add_option("--device", o->plan.device, "Vulkan device name (substring); default: $POND_DEVICE, else the most capable");
  sub->add_option("--only", o->plan.only, "Only these groups: gpu frame cpu lod bodies")->expected(1, -1);
  sub->add_flag("--validation", o->plan.validation, "Vulkan validation on; any message fails the run (for tests)");
  return {sub, [o] { return run_bench(*o); }};
}

}  // namespace pond::app
