#include "app/bench/report.h"

#include <algorithm>

namespace pond::bench {

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double Figure::median() const { return median_of(samples); }
double Figure::min() const { return samples.empty() ? 0 : *std::min_element(samples.begin(), samples.end()); }
double Figure::max() const { return samples.empty() ? 0 : *std::max_element(samples.begin(), samples.end()); }

const Figure* Report::find(const std::string& name) const {
  for (const Figure& f : figures)
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace pond::bench
