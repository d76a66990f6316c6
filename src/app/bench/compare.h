#pragma once
// --compare: each figure of this run against the same figure of an earlier run's JSON, as a ratio
// oriented so that above 1 is better (node-steps/s new/old, ms old/new). A figure worse than the
// baseline by more than the tolerance is a regression.
#include <string>
#include <vector>

#include "app/bench/report.h"

namespace pond::bench {

struct Comparison {
  std::string name, what;
  double baseline = 0, now = 0;
  double ratio = 1;         // > 1: better than the baseline
  bool regressed = false;   // ratio < 1 - tolerance
};

// The figures both reports have, in this run's order. tolerance: a fraction (0.2 = 20 %).
std::vector<Comparison> compare(const Report& now, const Report& baseline, double tolerance);
void print_comparison(const std::vector<Comparison>& rows, const std::string& baseline_source, double tolerance);

}  // namespace pond::bench
