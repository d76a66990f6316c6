#include "app/bench/table.h"

#include <cstdio>
#include <string>

namespace pond::bench {
namespace {

// A value with 4 significant digits and an SI prefix for large rates: "812.3 M".
std::string value_text(double v, const std::string& unit) {
  char text[32];
  if (unit == "node-steps/s") std::snprintf(text, sizeof text, "%.4g M", v * 1e-6);
  else std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// `text` padded with spaces to `width` characters (UTF-8: "²" is one character, two bytes).
std::string padded(const std::string& text, std::size_t width) {
  std::size_t chars = 0;
  for (const unsigned char c : text) chars += (c & 0xC0) != 0x80;
  return text + std::string(chars < width ? width - chars : 0, ' ');
}

}  // namespace

void print_table(const Report& r) {
  std::printf("pond bench: %s, %s\n", r.version.c_str(), r.date.c_str());
  std::printf("machine: %s, %d cores,", r.machine.cpu.c_str(), r.machine.cores);
  for (const std::string& s : r.machine.instruction_sets) std::printf(" %s", s.c_str());
  std::printf(", %.1f GiB, load %.2f\n", static_cast<double>(r.machine.memory_bytes) / (1u << 30),
              r.machine.load_average);
  if (r.device)
    std::printf("device: %s (%s), driver %s %s, Vulkan %s, %s\n", r.device->name.c_str(), r.device->type.c_str(),
                r.device->driver.c_str(), r.device->driver_version.c_str(), r.device->api_version.c_str(),
                r.device->timestamps ? "timestamps" : ("no timestamps: " + r.device->no_timestamps).c_str());
  std::printf("\n%-24s %-62s %12s %21s %-13s %s\n", "figure", "what", "median", "spread (least-most)", "unit", "");
  for (const Figure& f : r.figures) {
    std::string extra;
    if (f.hash) extra = "hash " + *f.hash;
    if (f.triangles) extra = std::to_string(*f.triangles) + " triangles";
    const std::string spread = value_text(f.min(), f.unit) + " - " + value_text(f.max(), f.unit);
    std::printf("%-24s %s %12s %21s %-13s %s\n", f.name.c_str(), padded(f.what, 62).c_str(), value_text(f.median(), f.unit).c_str(),
                spread.c_str(), f.unit.c_str(), extra.c_str());
  }
  for (const std::string& n : r.notes) std::printf("note: %s\n", n.c_str());
  if (!r.hashes_agree) std::printf("the CPU backends' state hashes differ (see the notes)\n");
}

}  // namespace pond::bench
