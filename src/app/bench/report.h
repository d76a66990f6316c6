#pragma once
// What `pond bench` measured: each figure with its repeated samples (the table and the JSON give
// the median and the spread), the machine and the device it ran on. Written and read as JSON
// (report_json.h) against bench/schema.json.
#include <cstdint>
#include <optional>
#include <utility>
#include <string>
#include <vector>

namespace pond::bench {

struct Figure {
  std::string name;   // stable id, what --compare matches: "cpu.avx2.t1.256"
  std::string what;   // for people: "CPU solver, avx2, 1 thread, 256²"
  std::string unit;   // "node-steps/s", "ms", "%"
  bool higher_is_better = true;
  std::vector<double> samples;            // one per repeat
  std::optional<std::string> hash;        // the state's 64-bit hash after the run (solver figures)
  std::optional<std::int64_t> triangles;  // the LOD's triangles (LOD figures)
  double median() const;
  double min() const;
  double max() const;
};

// A figure without samples yet.
inline Figure make_figure(std::string name, std::string what, std::string unit, bool higher_is_better = true) {
  Figure f;
  f.name = std::move(name), f.what = std::move(what), f.unit = std::move(unit), f.higher_is_better = higher_is_better;
  return f;
}

struct Machine {
  std::string cpu;                            // /proc/cpuinfo's model name, family and model
  int cores = 0;                              // logical CPUs pond may use
  std::vector<std::string> instruction_sets;  // the SIMD sets the solver may choose: "sse2", "avx2", ...
  std::uint64_t memory_bytes = 0;
  double load_average = 0;  // /proc/loadavg's last minute when the run began: other work on the cores
};

struct Device {
  std::string name, type, driver, driver_version, api_version;
  bool timestamps = false;     // per-pass GPU times from timestamp queries
  std::string no_timestamps;   // why not, when not
};

struct Report {
  std::string version;  // pond's
  std::string date;     // YYYY-MM-DD (UTC)
  bool quick = false;
  Machine machine;
  std::optional<Device> device;  // none when no GPU figure ran
  std::vector<Figure> figures;
  bool hashes_agree = true;      // every CPU backend's state hash equal, per size
  std::vector<std::string> notes;  // what was skipped and why

  Figure& add(Figure f) { return figures.emplace_back(std::move(f)); }
  const Figure* find(const std::string& name) const;
};

double median_of(std::vector<double> values);

}  // namespace pond::bench
