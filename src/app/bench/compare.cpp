#include "app/bench/compare.h"

#include <cstdio>
#include <limits>

namespace pond::bench {

std::vector<Comparison> compare(const Report& now, const Report& baseline, double tolerance) {
  std::vector<Comparison> rows;
  for (const Figure& f : now.figures) {
    const Figure* b = baseline.find(f.name);
    if (!b || b->unit != f.unit) continue;
    Comparison c{.name = f.name, .what = f.what, .baseline = b->median(), .now = f.median()};
    const double num = f.higher_is_better ? c.now : c.baseline, den = f.higher_is_better ? c.baseline : c.now;
    c.ratio = den > 0 ? num / den : (num > 0 ? std::numeric_limits<double>::infinity() : 1.0);
    c.regressed = c.ratio < 1.0 - tolerance;
    rows.push_back(c);
  }
  return rows;
}

void print_comparison(const std::vector<Comparison>& rows, const std::string& source, double tolerance) {
  std::printf("\nagainst %s (ratio > 1: better; tolerance %g %%):\n", source.c_str(), 100 * tolerance);
  if (rows.empty()) std::printf("  no figure in common\n");
  for (const Comparison& c : rows)
    std::printf("  %-26s %12.4g -> %12.4g  %6.3fx%s\n", c.name.c_str(), c.baseline, c.now, c.ratio,
                c.regressed ? "  REGRESSED" : "");
}

}  // namespace pond::bench
