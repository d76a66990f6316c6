#include "app/bench/plan.h"

#include <algorithm>

#include "core/errors.h"

namespace pond::bench {

bool Plan::runs(const std::string& group) const {
  return only.empty() || std::find(only.begin(), only.end(), group) != only.end();
}

std::vector<int> Plan::solver_sizes() const { return quick ? std::vector<int>{64, 128} : std::vector<int>{256, 1024}; }

std::vector<int> Plan::lod_sizes() const {
  return quick ? std::vector<int>{129, 257} : std::vector<int>{257, 1025, 2049, 4097};
}

void check_groups(const std::vector<std::string>& only) {
  const std::vector<std::string>& names = group_names();
  for (const std::string& g : only)
    if (std::find(names.begin(), names.end(), g) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError("--only: unknown figure group '" + g + "' (the groups: " + list + ")");
    }
}

}  // namespace pond::bench
