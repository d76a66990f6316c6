#include "app/cli_parse.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/errors.h"
#include "core/text.h"

namespace pond::app {
namespace {

bool parse_double(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(out);
}

// Decimal digits with an optional leading minus, no spaces, no exponent; false when it does not
// fit an int64.
bool parse_int64(const std::string& s, std::int64_t& out) {
  const std::size_t first = !s.empty() && s[0] == '-' ? 1 : 0;
  if (s.size() == first || s.size() - first > 19) return false;
  for (std::size_t k = first; k < s.size(); ++k)
    if (s[k] < '0' || s[k] > '9') return false;
  errno = 0;
  char* end = nullptr;
  out = std::strtoll(s.c_str(), &end, 10);
  return errno == 0 && end == s.c_str() + s.size();
}

}  // namespace

Size2 parse_size(const std::string& text, const char* option) {
  const auto x = text.find('x');
  Size2 s;
  std::int64_t w = 0, h = 0;
  if (x != std::string::npos && parse_int64(text.substr(0, x), w) && parse_int64(text.substr(x + 1), h) &&
      w > 0 && h > 0 && w <= 65536 && h <= 65536) {
    s.width = static_cast<int>(w);
    s.height = static_cast<int>(h);
    return s;
  }
  throw InputError(std::string(option) + " " + quote(text) +
                   " must be WIDTHxHEIGHT with both between 1 and 65536, e.g. 1280x720");
}

std::array<double, 3> parse_vec3(const std::string& text, const char* option) {
  std::array<double, 3> v{};
  std::size_t start = 0;
  for (int k = 0; k < 3; ++k) {
    const std::size_t comma = text.find(',', start);
    const bool last = k == 2;
    if ((comma == std::string::npos) != last ||
        !parse_double(text.substr(start, last ? std::string::npos : comma - start), v[k]))
      throw InputError(std::string(option) + " " + quote(text) + " must be three finite numbers X,Y,Z");
    start = comma + 1;
  }
  return v;
}

sim::SolverChoice parse_solver(const std::string& name, sim::MathMode math, int threads) {
  sim::SolverChoice c{.gpu = name == "gpu", .threads = threads, .math = math};
  if (!c.gpu) c.backend = name == "auto" ? sim::best_backend() : *sim::parse_backend(name);
  return c;
}

CLI::Validator whole_number(std::int64_t lo, std::int64_t hi) {
  const std::string range = "from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        std::int64_t v = 0;
        if (!parse_int64(text, v) || v < lo || v > hi)
          return "must be a whole number " + range + " in decimal digits, not " + quote(text);
        text = std::to_string(v);
        return {};
      },
      "INT in [" + std::to_string(lo) + " - " + std::to_string(hi) + "]");
}

CLI::Validator real_number(double lo, double hi, std::string what) {
  const bool positive = lo > 0 && lo < 1e-300;  // (0, hi]
  const std::string help = std::string(positive ? "in (0" : "in [" + number_text(lo)) + " - " + number_text(hi) + "]";
  return CLI::Validator(
      [lo, hi, what](std::string& text) -> std::string {
        double v = 0;
        if (!parse_double(text, v) || !(v >= lo && v <= hi)) return "must be " + what + ", not " + quote(text);
        char exact[32];
        std::snprintf(exact, sizeof exact, "%.17g", v);
        text = exact;
        return {};
      },
      help);
}

}  // namespace pond::app
