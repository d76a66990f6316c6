#include "app/cli_parse.h"

#include <cmath>
#include <cstdlib>

#include "core/errors.h"

namespace pond::app {
namespace {
bool parse_double(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(out);
}
}  // namespace

Size2 parse_size(const std::string& text, const char* option) {
  const auto x = text.find('x');
  Size2 s;
  char* end = nullptr;
  if (x != std::string::npos && x > 0 && x + 1 < text.size()) {
    const long w = std::strtol(text.c_str(), &end, 10);
    if (end == text.c_str() + x) {
      const long h = std::strtol(text.c_str() + x + 1, &end, 10);
      if (end == text.c_str() + text.size() && w > 0 && h > 0 && w <= 65536 && h <= 65536) {
        s.width = static_cast<int>(w);
        s.height = static_cast<int>(h);
        return s;
      }
    }
  }
  throw InputError(std::string(option) + " '" + text +
                   "' must be WIDTHxHEIGHT with both between 1 and 65536, e.g. 1280x720");
}

std::array<double, 3> parse_vec3(const std::string& text, const char* option) {
  std::array<double, 3> v{};
  std::size_t start = 0;
  for (int k = 0; k < 3; ++k) {
    const std::size_t comma = text.find(',', start);
    const bool last = k == 2;
    if ((comma == std::string::npos) != last ||
        !parse_double(text.substr(start, last ? std::string::npos : comma - start), v[k]))
      throw InputError(std::string(option) + " '" + text + "' must be three finite numbers X,Y,Z");
    start = comma + 1;
  }
  return v;
}

sim::SolverChoice parse_solver(const std::string& name, sim::MathMode math, int threads) {
  sim::SolverChoice c{.gpu = name == "gpu", .threads = threads, .math = math};
  if (!c.gpu) c.backend = name == "auto" ? sim::best_backend() : *sim::parse_backend(name);
  return c;
}

}  // namespace pond::app
