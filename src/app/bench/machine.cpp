#include "app/bench/machine.h"

#include <fstream>
#include <string>
#include <thread>

#include "core/cpu_features.h"

namespace pond::bench {
namespace {

// The value of the first "key : value" line of a /proc file whose key is `key`; "" when none.
std::string proc_value(const char* file, const std::string& key) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string k = line.substr(0, colon);
    while (!k.empty() && (k.back() == ' ' || k.back() == '\t')) k.pop_back();
    if (k != key) continue;
    std::size_t v = colon + 1;
    while (v < line.size() && line[v] == ' ') ++v;
    return line.substr(v);
  }
  return {};
}

}  // namespace

Machine this_machine() {
  Machine m;
  m.cpu = proc_value("/proc/cpuinfo", "model name");
  if (m.cpu.empty()) m.cpu = "unknown CPU";
  const std::string family = proc_value("/proc/cpuinfo", "cpu family"), model = proc_value("/proc/cpuinfo", "model");
  if (!family.empty() && !model.empty()) m.cpu += " (family " + family + ", model " + model + ")";
  m.cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  using core::CpuFeature;
  for (auto [feature, name] : {std::pair{CpuFeature::sse2, "sse2"}, std::pair{CpuFeature::avx2, "avx2"},
                               std::pair{CpuFeature::avx512f, "avx512f"}})
    if (core::cpu_has(feature)) m.instruction_sets.push_back(name);
  const std::string mem = proc_value("/proc/meminfo", "MemTotal");  // "24683748 kB"
  if (!mem.empty()) m.memory_bytes = std::stoull(mem) * 1024;
  std::ifstream("/proc/loadavg") >> m.load_average;
  return m;
}

}  // namespace pond::bench
